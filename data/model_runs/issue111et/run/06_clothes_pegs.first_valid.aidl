# Request: one-piece clothes pegs for the washing line at the campsite, cut from 4 mm birch
# ply (no metal spring to lose). Each peg is 70 mm long, the jaws 16 mm wide: two jaws joined at
# the back by a round spring loop, outer diameter 22 mm and inner 16 mm (a 3 mm wall),
# centred on the peg's axis 59 mm from the tip. The jaws are split by a 1 mm slit from the
# lead-in to the loop's hole; at the tip a V lead-in 8 mm wide and 6 mm deep guides the line
# (4 mm paracord plus the cloth) into a 6 mm round seat centred 14 mm from the tip, where it
# snaps in. The tip's two corners rounded R3. My initials "JB" engraved, 3 mm tall, on the
# upper jaw 35 mm from the tip. A set of four, laid out one under the other 5 mm apart.

units mm
thickness 4 mm
kerf 0.15 mm

length = 70 mm
width = 16 mm
loop_x = 59 mm        # loop centre from the tip
loop_od = 22 mm
loop_id = 16 mm
seat_x = 14 mm
seat_d = 6 mm
slit = 1 mm
v_w = 8 mm
v_d = 6 mm

def clothes_peg() -> solid {
    jaws = RoundedRectangle(bottom_left=(0, -width / 2), width=loop_x - 4 mm, height=width,
                            corner_radii=[3, 0, 0, 3])
    loop = Circle(center=(loop_x, 0), diameter=loop_od)
    hole spring { c = Circle(center=(loop_x, 0), diameter=loop_id) }
    hole split {
        s = Rectangle(corner=(v_d - 1 mm, -slit / 2), opposite=(loop_x - loop_id / 2 + 1 mm, slit / 2))
    }
    hole lead_in {
        v = Polygon([(-1, (v_w / 2) * (v_d + 1) / v_d), (v_d, 0), (-1, -(v_w / 2) * (v_d + 1) / v_d)],
                    overrun=true)
    }
    hole seat { c = Circle(center=(seat_x, 0), diameter=seat_d) }
    drawing initials {
        t = Text("JB", position=(35, 4), size=3, valign="middle")
    }
    Fixed(jaws)
    AllowOverlap(spring, split)    # the slit opens into the loop's hole: one opening, meant
}

assembly peg_set {
    for i in range(4) {
        peg = clothes_peg()
    }
    for i in range(1, 4) {
        Below(peg[i], peg[i - 1], gap=5)
        AlignLeft(peg[i], peg[i - 1])
    }

    assert len(peg) == 4
    assert peg[0].loop.bb.right - peg[0].jaws.bb.left == 70 mm, "70 mm long"
    assert peg[0].jaws.bb.height == 16 mm, "16 mm wide"
    assert peg[0].loop.diameter == 22 mm and peg[0].spring.c.diameter == 16 mm
    assert peg[0].loop.center.x - peg[0].jaws.bb.left == 59 mm
    assert peg[0].seat.c.center.x - peg[0].jaws.bb.left == 14 mm and peg[0].seat.c.diameter == 6 mm
    assert peg[0].split.s.bb.height == 1 mm
    assert peg[0].split.s.bb.right > peg[0].spring.c.bb.left, "slit reaches the loop's hole"
    assert peg[0].lead_in.v.points[1].x - peg[0].jaws.bb.left == 6 mm, "lead-in 6 mm deep"
    assert peg[0].initials.t.position.x - peg[0].jaws.bb.left == 35 mm
    assert peg[0].bb.top - peg[1].bb.top == 22 mm + 5 mm, "5 mm apart (the loop is the widest)"
}
