# Request (workshop): a shadow board for my workshop wall, 500 x 400 mm, 6 mm plywood, 10 mm
# corner radius. Filled engraved silhouettes show where each tool goes: a claw hammer 280 mm
# long overall (head 120 x 28 mm), combination pliers 200 mm long, a screwdriver 250 mm long
# (handle 32 x 110 mm, shaft 7 mm), a tape measure 75 x 75 mm and a 300 x 25 mm steel rule
# lying along the bottom. Every tool rests on 6 mm dowel pegs in 6.2 mm holes (two per tool,
# one between the pliers' handles). Title "PUT IT BACK" engraved filled, 14 mm bold letters,
# centred at the top. Four 4.5 mm screw holes 15 mm in from each corner, countersunk for
# 9 mm heads.

thickness 6 mm

param peg_d = 6.2 mm, min = 5 mm, max = 10 mm

solid board {
    body = RoundedRectangle(center=(0, 0), width=500, height=400, corner_radius=10)

    drawing title {
        t = Text("PUT IT BACK", position=(0, 170), size=14, font="sans:Bold", fill=true)
    }

    drawing shadows {
        # claw hammer at x = -170, head up
        ham_face = RoundedRectangle(center=(-195, 115), width=70, height=28, corner_radius=4)
        ham_claw = Hull(Rectangle(center=(-150, 115), width=20, height=28),
                        Circle(center=(-116, 106), radius=4))
        ham_handle = RoundedRectangle(center=(-170, -20.5), width=30, height=261,
                                      corner_radius=10, fill=true)
        ham_head = Hull(ham_face, ham_claw, fill=true)

        # combination pliers at x = -55: jaw, pivot, two handles
        jaw = Hull(Circle(center=(-55, 116), radius=9), Circle(center=(-55, 70), radius=16),
                   fill=true)
        grip_l = Stroke(Line((-55, 70), (-72, -68)), width=14, fill=true)
        grip_r = Stroke(Line((-55, 70), (-38, -68)), width=14, fill=true)

        # screwdriver at x = 55
        sd_handle = RoundedRectangle(center=(55, 75), width=32, height=110, corner_radius=8,
                                     fill=true)
        sd_shaft = Rectangle(center=(55, -49), width=7, height=142, fill=true)

        # tape measure at x = 175
        tape = RoundedRectangle(center=(175, 90), width=75, height=75, corner_radius=12,
                                fill=true)

        # steel rule along the bottom
        rule = Rectangle(center=(0, -170), width=300, height=25, fill=true)
    }

    hole pegs {
        h1 = Circle(center=(-190, 97.4), diameter=peg_d)
        h2 = Circle(center=(-150, 97.4), diameter=peg_d)
        p1 = Circle(center=(-55, -50), diameter=peg_d)
        s1 = Circle(center=(45, 16.4), diameter=peg_d)
        s2 = Circle(center=(65, 16.4), diameter=peg_d)
        t1 = Circle(center=(155, 48.9), diameter=peg_d)
        t2 = Circle(center=(195, 48.9), diameter=peg_d)
        r1 = Circle(center=(-100, -186.1), diameter=peg_d)
        r2 = Circle(center=(100, -186.1), diameter=peg_d)
    }

    hole screw { c = Circle(center=(0, 0), diameter=4.5) }
    screws = CornerPattern(screw, body, inset=15)
    Countersink(screws, diameter=9)

    assert body.width == 500 mm and body.height == 400 mm, "board 500 x 400"
    assert shadows.ham_head.bb.top - shadows.ham_handle.bb.bottom == 280 mm, "hammer 280 long"
    assert shadows.ham_head.bb.width == 120 mm, "hammer head 120"
    assert shadows.jaw.bb.top - shadows.grip_l.bb.bottom == 200 mm, "pliers 200 long"
    assert shadows.sd_handle.bb.top - shadows.sd_shaft.bb.bottom == 250 mm, "screwdriver 250"
    assert shadows.rule.bb.width == 300 mm, "rule 300"
    assert len(screws) == 4
    assert title.t.size == 14 mm
}
