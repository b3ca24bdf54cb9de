# Request (gifts): a wooden thank-you card, 3 mm birch ply, one piece that folds like a book on
# a living hinge: 320 x 140 mm unfolded (corners rounded 6 mm), a 20 mm hinge band up the
# middle (2 mm pitch, 15 mm cuts, 3 mm bridges), so each leaf is 150 x 140. The cut face is the
# outside: the right leaf is the front cover, with a 68 mm wide heart cut through near the
# top (two 18 mm radius lobes 32 mm apart, its point 38 mm below their centres) and
# "THANK" / "YOU" cut through below it as 20 mm bold stencil letters; the left leaf is the back
# cover, with "made by Sam - 2026" engraved 5 mm high, 15 mm above its bottom edge, centred.
# Shown assembled standing open as a tent, the leaves 60 deg apart.

units mm
thickness 3 mm

import "std/plates.aidl"

card_w = 320 mm
card_h = 140 mm
band = 20 mm
leaf_w = (card_w - band) / 2
front_x = band / 2 + leaf_w / 2     # middle of the front leaf
back_x = -front_x
lobe_r = 18 mm
lobe_dx = 32 mm
heart_y = 38 mm                      # lobes' centres
point_drop = 38 mm

assembly card_kit {
    solid card {
        body = RoundedRectangle(center=(0, 0), width=card_w, height=card_h, corner_radius=6)
        Fixed(body)
        hinge = living_hinge(width=band, height=card_h, pitch=2, cut=15, bridge=3, cx=0, cy=0)
        hole heart {
            left_lobe = Hull(Circle(center=(front_x - lobe_dx / 2, heart_y), radius=lobe_r),
                             Point(front_x, heart_y - point_drop))
            right_lobe = Hull(Circle(center=(front_x + lobe_dx / 2, heart_y), radius=lobe_r),
                              Point(front_x, heart_y - point_drop))
        }
        hole words {
            l1 = Text("THANK", position=(front_x, -25), size=20, font="sans:Bold", stencil=true)
            l2 = Text("YOU", position=(front_x, -52), size=20, font="sans:Bold", stencil=true)
        }
        drawing maker {
            m = Text("made by Sam - 2026", position=(back_x, -card_h / 2 + 15), size=5)
        }
    }
    # standing on its bottom edge, spine up z, folded round the band's middle line
    Place(card, position=(0, 0, card_h / 2), rotation=(90 deg, 0, 0))
    Bend(card, at=0, angle=-120 deg, radius=band / (120 deg / 1 rad) - 1.5 mm)

    assert card.body.width == 320 mm and card.body.height == 140 mm, "320 x 140 unfolded"
    assert leaf_w == 150 mm, "leaves 150 wide"
    assert card.hinge.width == 20 mm, "20 mm band"
    assert card.heart.bb.width == 68 mm, "68 mm heart"
    assert card.heart.bb.left - band / 2 >= 10 mm and leaf_w + band / 2 - card.heart.bb.right >= 10 mm,
        "heart inside the front leaf"
    assert card.body.bb.top - card.heart.bb.top >= 10 mm, "heart clear of the top"
    assert card.words.l1.bb.top <= card.heart.bb.bottom - 3 mm, "THANK under the heart"
    assert card.words.l1.bb.left - band / 2 >= 10 mm, "words clear of the hinge"
    assert card.maker.m.position.y - card.body.bb.bottom == 15 mm, "maker line 15 up"
    assert card.maker.m.bb.right <= -band / 2 - 10 mm, "maker line on the back leaf"
}
