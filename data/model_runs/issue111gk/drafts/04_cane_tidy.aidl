# Request: a garden-cane tidy for the shed, 6 mm exterior ply. Two 250 mm discs held 300 mm
# apart (clear) by three legs 40 mm wide that stand radially at the rim, 120 degrees apart,
# between the cane holes. The top disc has 19 holes of 22 mm for canes (one in the middle,
# 6 on a 90 mm circle, 12 on a 176 mm circle); the bottom disc has a 10 mm drain hole under
# each. Each leg has one 20 mm tenon into each disc (0.2 mm clearance), its outer edge flush
# with the rim, and a 200 x 14 mm lightening slot. "GARDEN CANES" engraved 8 mm tall over the
# top of the top disc, along its rim.

import "std/joints.aidl"

thickness 6 mm

leg_angle = 15 deg

def disc_plate(hole_d=22 mm) -> solid {
    disc = Circle(center=(0, 0), diameter=250)
    hole c0 { c = Circle(center=(0, 0), diameter=hole_d) }
    hole c1 { c = Circle(center=(45, 0), diameter=hole_d) }
    hole c2 { c = Circle(center=(88, 0), diameter=hole_d) }
    ring1 = CircularPattern(c1, 6, (0, 0))
    ring2 = CircularPattern(c2, 12, (0, 0))
    hole mortise {
        m = tab_and_slot(part="slot", length=40 mm, thickness=6 mm, tabs=1, tab=20 mm,
                         screw=0, clearance=0.2 mm, rotation=leg_angle,
                         cx=105 mm * cos(leg_angle), cy=105 mm * sin(leg_angle))
    }
    mortises = CircularPattern(mortise, 3, (0, 0))
}

# a leg as drawn: x is the radius (85 to 125), y the height, tenon tips at 0 and 312
def leg() -> solid {
    body = Rectangle(bottom_left=(85, 0), width=40, height=300 + 2 * 6)
    foot = tab_and_slot(part="tab", length=40 mm, thickness=6 mm, tabs=1, tab=20 mm,
                        screw=0, rotation=180 deg, cx=105 mm, cy=0 mm)
    head = tab_and_slot(part="tab", length=40 mm, thickness=6 mm, tabs=1, tab=20 mm,
                        screw=0, rotation=0 deg, cx=105 mm, cy=312 mm)
    hole lighten { s = Slot(center=(105, 156), length=200, width=14, rotation=90) }
}

assembly cane_tidy {
    top = disc_plate(hole_d=22 mm)
    bottom = disc_plate(hole_d=10 mm)
    leg_a = leg()
    leg_b = leg()
    leg_c = leg()

    drawing label {
        rim = Circle(center=(0, 0), radius=112, construction=true)
        t = Text("GARDEN CANES", along=rim, size=8, valign="middle")
    }
    Concentric(label.rim, top.disc)
    CutInto(label, top)

    # on the sheet
    RightOf(bottom, top, gap=10)
    AlignTop(bottom, top)
    RightOf(leg_a, bottom, gap=10)
    AlignTop(leg_a, bottom)
    RightOf(leg_b, leg_a, gap=10)
    AlignTop(leg_b, leg_a)
    RightOf(leg_c, leg_b, gap=10)
    AlignTop(leg_c, leg_b)

    # assembled: discs flat, legs standing radially, their mid-plane on the mortises' line
    Place(bottom, position=(0, 0, 0), face="up")
    Place(top, position=(0, 0, 306), face="up")
    Place(leg_a, position=(-3 * sin(leg_angle), 3 * cos(leg_angle), 0),
          rotation=(90 deg, 0, leg_angle))
    Place(leg_b, position=(-3 * sin(leg_angle + 120 deg), 3 * cos(leg_angle + 120 deg), 0),
          rotation=(90 deg, 0, leg_angle + 120 deg))
    Place(leg_c, position=(-3 * sin(leg_angle + 240 deg), 3 * cos(leg_angle + 240 deg), 0),
          rotation=(90 deg, 0, leg_angle + 240 deg))

    assert top.disc.diameter == 250 mm, "250 mm discs"
    assert 1 + len(top.ring1) + len(top.ring2) == 19, "19 cane holes"
    assert top.c0.c.diameter == 22 mm and bottom.c0.c.diameter == 10 mm, "22 mm holes, 10 drains"
    assert top.c1.c.center.x * 2 == 90 mm and top.c2.c.center.x * 2 == 176 mm,
        "holes on 90 and 176 mm circles"
    assert leg_a.body.bb.height - 2 * 6 mm == 300 mm, "300 mm clear between the discs"
    assert leg_a.body.bb.right == 125 mm, "the leg flush with the 250 mm disc's rim"
    assert distance(top.mortises, top.ring2) >= 5 mm, "mortises clear of the cane holes"
    assert distance(top.mortises, top.ring1) >= 5 mm, "mortises clear of the cane holes"
    assert label.t.size == 8 mm, "8 mm lettering"
}
