# Request (gifts): "52 reasons I love you": a deck of 52 cards in a sliding-lid box.
# - Box from 3 mm ply, finger-jointed (10 mm fingers), with a sliding lid; the space inside
#   92 x 66 mm and 22 mm high, for 63 x 88 mm cards.
# - On the lid: a heart window cut through (the top card shows), 30 mm wide, 10 mm from
#   the lid's back end; under it "52 Reasons I Love You" engraved filled (serif bold italic,
#   6 mm, one line), between the heart and the finger pull the lid comes with (the template's
#   own `pull`: my 20 x 6 finger slot overlapped it, W0508, so it is left to the template).
# - 52 cards 63 x 88 mm (R3 corners) cut from 0.35 mm card, each with its number engraved
#   filled (serif bold, 8 mm) in the top-left corner and upside down in the bottom-right,
#   6 mm in; the reasons are written by hand. The cards lie flat in the box.

import "std/boxes.aidl"

thickness 3 mm

card_w = 63 mm
card_h = 88 mm
card_t = 0.35 mm
n_cards = 52
inside_l = 92 mm
inside_w = 66 mm
inside_h = 22 mm

def card(n=1) -> solid {
    thickness 0.35 mm
    body = RoundedRectangle(center=(0, 0), width=card_w, height=card_h, corner_radius=3)
    drawing num {
        top = Text(str(n), position=(-card_w / 2 + 6 mm, card_h / 2 - 6 mm), size=8,
                   font="serif:Bold", anchor="start", valign="top", fill=true)
        bottom = Text(str(n), position=(card_w / 2 - 6 mm, -card_h / 2 + 6 mm), size=8,
                      font="serif:Bold", anchor="start", valign="top", fill=true,
                      rotation=180 deg)
    }
    Fixed(body)
}

assembly gift {
    box = sliding_lid_box(length=inside_l, width=inside_w, height=inside_h, thickness=3 mm,
                          finger=10 mm, outside=false)

    hole heart {
        a = Hull(Circle(center=(-7, 4), radius=8), Point(0, -14))
        b = Hull(Circle(center=(7, 4), radius=8), Point(0, -14))
        Rigid(self)
    }
    AlignCenterX(heart, box.lid)
    heart.bb.top == box.lid.bb.top - 10 mm
    CutInto(heart, box.lid)

    drawing words {
        l1 = Text("52 Reasons I Love You", position=(0, 0), size=6, font="serif:Bold Italic",
                  valign="middle", fill=true, max_width=80 mm)
    }
    AlignCenterX(words, box.lid)
    words.l1.position.y == (heart.bb.bottom + box.lid.pull.bb.top) / 2
    CutInto(words, box.lid)

    for i in range(n_cards) {
        c = card(n=i + 1)
        c.bb.center_x == box.bb.right + 20 mm + card_w / 2 + (i % 13) * (card_w + 4 mm)
        c.bb.center_y == box.bb.bottom + card_h / 2 + (i // 13) * (card_h + 4 mm)
        Place(c, position=(0, 0, 3 mm + i * card_t), face="up", up="right")
    }

    # the request's numbers
    assert len(c) == 52, "52 cards"
    assert c[0].body.bb.width == 63 mm and c[0].body.bb.height == 88 mm, "63 x 88 cards"
    assert inside_l >= card_h + 2 mm and inside_w >= card_w + 2 mm, "cards fit with play"
    assert n_cards * card_t <= inside_h - 2 mm, "the deck fits under the lid"
    assert heart.bb.width == 30 mm, "heart 30 wide"
    assert box.lid.bb.top - heart.bb.top == 10 mm, "heart 10 from the back end"
    assert distance(words, box.lid.pull) >= 2 mm, "words clear of the finger pull"
    assert distance(words, heart) >= 3 mm, "words clear of the heart"
    assert words.bb.width <= box.lid.bb.width - 16 mm, "words within the lid"
    assert c[51].num.top.bb.left - c[51].body.bb.left >= 5 mm, "number 6 in"
    assert distance(c[51].num.top, c[51].num.bottom) >= 20 mm, "numbers apart"
}
