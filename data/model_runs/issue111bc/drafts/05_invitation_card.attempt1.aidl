# Request (parties): "Our wedding invitations, laser-cut from 300 gsm white card (0.35 mm):
# a 120 x 170 mm card with a scalloped lace edge (bumps 11 mm across at 10 mm pitch, centred
# on the card's edge, so 131 x 181 overall: it must fit an A7 envelope, 133 x 184), a lace
# row of 2 mm holes 10 mm in from the card's edge at 10 mm pitch all round, a heart (24 mm
# wide) cut out near the top, our names 'Anna & Tom' cut through as 14 mm bold serif stencil
# letters, and the wording engraved in 3.5 mm single-line capitals: TOGETHER WITH THEIR
# FAMILIES / (names) / INVITE YOU TO CELEBRATE THEIR WEDDING / SATURDAY 12 JUNE 2027 /
# 3 PM, ROSE BARN, DEVON / and at the foot, RSVP BY 1 MAY."

thickness 0.35 mm
kerf 0.1 mm

card_w = 120 mm
card_h = 170 mm
bump_d = 11 mm
pitch = 10 mm
lace_in = 10 mm

solid card {
    body = Rectangle(center=(0, 0), width=card_w, height=card_h)

    # the scalloped edge: bumps centred on the edge line
    for i in range(13) {
        top_bump = Circle(center=(-card_w / 2 + i * pitch, card_h / 2), diameter=bump_d)
        bottom_bump = Circle(center=(-card_w / 2 + i * pitch, -card_h / 2), diameter=bump_d)
    }
    for j in range(1, 17) {
        left_bump = Circle(center=(-card_w / 2, -card_h / 2 + j * pitch), diameter=bump_d)
        right_bump = Circle(center=(card_w / 2, -card_h / 2 + j * pitch), diameter=bump_d)
    }

    # the lace row of holes, 10 mm in: a 100 x 150 ring of holes at 10 mm pitch
    hole lace {
        for i in range(11) {
            top_h = Circle(center=(-50 + i * pitch, 75), diameter=2)
            bottom_h = Circle(center=(-50 + i * pitch, -75), diameter=2)
        }
        for j in range(1, 15) {
            left_h = Circle(center=(-50, -75 + j * pitch), diameter=2)
            right_h = Circle(center=(50, -75 + j * pitch), diameter=2)
        }
    }

    # a heart near the top: two lobes, each the hull of a circle and the point
    hole heart {
        lobe_l = Hull(Circle(center=(-5.3, 53.3), radius=6.7), Point(0, 37.3))
        lobe_r = Hull(Circle(center=(5.3, 53.3), radius=6.7), Point(0, 37.3))
    }

    hole names {
        n = Text("Anna & Tom", position=(0, 10), size=14, font="serif:Bold", stencil=true,
                 valign="middle")
    }

    drawing words {
        w1 = Text("TOGETHER WITH THEIR FAMILIES", position=(0, 27), size=3.5, valign="middle")
        w2 = Text("INVITE YOU TO CELEBRATE THEIR WEDDING", position=(0, -7), size=3.5,
                  valign="middle")
        w3 = Text("SATURDAY 12 JUNE 2027", position=(0, -25), size=3.5, valign="middle")
        w4 = Text("3 PM, ROSE BARN, DEVON", position=(0, -33), size=3.5, valign="middle")
        w5 = Text("RSVP BY 1 MAY", position=(0, -60), size=3.5, valign="middle")
    }

    # the request's numbers
    assert self.bb.width == 131 mm and self.bb.height == 181 mm, "131 x 181 overall"
    assert self.bb.width <= 133 mm and self.bb.height <= 184 mm, "fits an A7 envelope"
    assert len(top_bump) == 13 and top_bump[1].center.x - top_bump[0].center.x == 10 mm,
        "10 mm pitch"
    assert body.bb.top - lace.top_h[0].center.y == 10 mm, "lace 10 mm in"
    assert lace.right_h[0].center.x == body.bb.right - 10 mm, "lace 10 mm in at the side"
    assert abs(heart.bb.width - 24 mm) < 0.1 mm, "heart 24 mm wide"
    assert names.n.size == 14 mm and words.w1.size == 3.5 mm, "letter sizes"
    # everything engraved or cut stays inside the lace row
    assert words.bb.width < 96 mm and names.bb.width < 96 mm, "wording inside the lace"
}
