# Request (gifts): a hollow "book" to hide a gift in, for my brother, from 3 mm ply layers
# glued in a stack. The book is 150 wide x 210 tall, its spine (left) edge bowed out 6 mm
# in a curve like a hardback's. A solid back cover, twelve page layers each with a
# 110 x 170 R5 cavity centred, and a lift-off lid: the front cover with a lip plate glued
# under it that drops into the cavity with 0.3 mm clearance all round (a 3 mm lip, R5 less
# the clearance). The top two page layers have an R12 thumb notch centred on the right
# (fore-edge) so I can lift the lid. On the lid, engraved: a border line 8 mm in from the
# straight edges (R3 corners), the title SECRETS filled in bold serif with 16 mm caps,
# centred 40 mm above the middle, and "A NOVEL" in plain strokes, 5 mm, centred 20 mm above
# the middle.

thickness 3 mm

t = 3 mm
book_w = 150 mm
book_h = 210 mm
bow = 6 mm
cav_w = 110 mm
cav_h = 170 mm
cav_r = 5 mm
pages = 12
clear = 0.3 mm

def book_outline() -> solid {
    # the spine edge an arc bowed `bow` out to the left, the other three edges straight
    spine = Arc(start=(-book_w / 2, -book_h / 2), through=(-book_w / 2 - bow, 0),
                end=(-book_w / 2, book_h / 2))
    top = Line(spine.end, (book_w / 2, book_h / 2))
    fore = Line(top.end, (book_w / 2, -book_h / 2))
    foot = Line(fore.end, spine.start)
}

def page(notch=false) -> solid {
    body = book_outline()
    hole cavity { r = RoundedRectangle(center=(0, 0), width=cav_w, height=cav_h, corner_radius=cav_r) }
    if notch {
        hole thumb { c = Circle(center=(book_w / 2, 0), radius=12, overrun=true) }
    }
}

assembly book_safe {
    solid back_cover { body = book_outline() }
    for i in range(pages) {
        p = page(notch=i >= pages - 2)
    }
    solid lid {
        body = book_outline()
        drawing art {
            border = RoundedRectangle(center=(0, 0), width=book_w - 16, height=book_h - 16,
                                      corner_radius=3)
            title = Text("SECRETS", position=(0, 40), size=16, font="serif:Bold", valign="middle",
                         fill=true)
            sub = Text("A NOVEL", position=(0, 20), size=5, valign="middle")
        }
    }
    solid lip {
        plate = RoundedRectangle(center=(0, 0), width=cav_w - 2 * clear, height=cav_h - 2 * clear,
                                 corner_radius=cav_r - clear)
    }

    # assembled: the stack on z = 0, the lid's art facing up
    Place(back_cover, position=(0, 0, 0), face="up")
    for i in range(pages) {
        Place(p[i], position=(0, 0, t + i * t), face="up")
    }
    Place(lip, position=(0, 0, pages * t), face="up")
    Place(lid, position=(0, 0, (pages + 1) * t), face="up")

    # laid out flat: the pages in two rows of six, the covers and the lip in a third row
    for i in range(1, pages) {
        if i == 6 {
            Below(p[6], p[0], gap=5)
            AlignLeft(p[6], p[0])
        } else {
            RightOf(p[i], p[i - 1], gap=5)
            AlignTop(p[i], p[i - 1])
        }
    }
    Below(back_cover, p[6], gap=5)
    AlignLeft(back_cover, p[6])
    RightOf(lid, back_cover, gap=5)
    AlignTop(lid, back_cover)
    RightOf(lip, lid, gap=5)
    AlignTop(lip, lid)

    # the request's numbers
    assert len(p) == 12, "twelve page layers"
    assert lid.body.bb.width == 156 mm and lid.body.bb.height == 210 mm, "150 x 210, spine bowed 6"
    assert p[0].cavity.r.width == 110 mm and p[0].cavity.r.height == 170 mm, "cavity 110 x 170"
    assert p[0].cavity.r.width - lip.plate.width == 0.6 mm, "lip 0.3 clear each side"
    assert lid.art.title.position.y - lid.body.spine.through.y == 40 mm, "title 40 above the middle"
    assert lid.art.sub.position.y - lid.body.spine.through.y == 20 mm, "subtitle 20 above"
    assert distance(lid.art.title, lid.art.border) >= 5 mm, "title clear of the border"
    assert p[11].thumb.c.radius == 12 mm and p[10].thumb.c.radius == 12 mm, "thumb notch on the top two"
}
