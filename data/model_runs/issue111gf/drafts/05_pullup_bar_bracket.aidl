# Request (sport): a pair of wall brackets for a 32 mm steel bar (a kids' pull-up / chin-up bar
# in the garage), 9 mm birch ply. Each bracket: a 100 x 220 mm wall plate (R6 corners) with
# four 5 mm countersunk wood screws (holes 5.5 mm, heads 10 mm) at +-30 mm across and +-90 mm
# up from its centre; and an arm, 9 mm thick, standing out of the plate's vertical centre line,
# glued into it by two 40 mm tenons through mortises (0.2 mm clearance) along a 160 mm root.
# The arm tapers from the root to a 60 mm round end whose 33 mm hole holds the bar 120 mm out
# from the wall. "MAX 40 kg" engraved on each arm's inner face (readable standing under the
# bar). Brackets 600 mm apart centre to centre.

units mm
thickness 9 mm

import "std/joints.aidl"

t = 9
root = 160
reach = 120
span = 600
z0 = 110   # the plates' centres above the floor of the 3D view

def wall_plate() -> solid {
    body = RoundedRectangle(center=(0, 0), width=100, height=220, corner_radius=6)
    for p in [(-30, -90), (30, -90), (30, 90), (-30, 90)] {
        hole screw { c = Circle(center=p, diameter=5.5) }
    }
    Countersink(screw, diameter=10)
    mortise = tab_and_slot(part="slot", length=root, thickness=t, tabs=2, tab=40, screw=0,
                           clearance=0.2, rotation=90, cx=0, cy=0)
}

def arm(text_turn=0 deg) -> solid {
    root_bar = Rectangle(bottom_left=(0, -root / 2), width=10, height=root, construction=true)
    end = Circle(center=(reach, 0), diameter=60, construction=true)
    web = Hull(root_bar, end)
    tenons = tab_and_slot(part="tab", length=root, thickness=t, tabs=2, tab=40, screw=0,
                          rotation=90, cx=0, cy=0)
    hole bar { c = Circle(center=(reach, 0), diameter=33) }
    drawing label {
        l = Text("MAX 40 kg", position=(55, 0), size=8, valign="middle", rotation=text_turn)
    }
}

assembly chin_up {
    plate_l = wall_plate()
    plate_r = wall_plate()
    arm_l = arm(text_turn=180 deg)
    arm_r = arm()

    # flat layout
    RightOf(plate_r, plate_l, gap=10)
    AlignBottom(plate_r, plate_l)
    RightOf(arm_l, plate_r, gap=10)
    AlignBottom(arm_l, plate_l)
    Above(arm_r, arm_l, gap=10)
    AlignLeft(arm_r, arm_l)

    # 3D: wall is the plane y = 0, plates on it facing out (-y); arms stand out toward -y,
    # their engraved faces turned inward, toward each other
    Place(plate_l, position=(0, 0, z0), face="front", up="up")
    Place(plate_r, position=(span, 0, z0), face="front", up="up")
    # FIX after the first valid program (W0517: arm_l ran 8.9 mm into plate_l): facing right,
    # the arm's top face is t toward +x from its position, so its bottom face is at -t / 2
    Place(arm_l, position=(-t / 2, 0, z0), face="right", up="down")
    Place(arm_r, position=(span + t / 2, 0, z0), face="left", up="up")

    assert plate_l.body.bb.width == 100 mm and plate_l.body.bb.height == 220 mm, "plate 100 x 220"
    assert len(plate_l.screw) == 4, "four screws"
    assert plate_l.screw[1].c.center.x - plate_l.screw[0].c.center.x == 60 mm, "+-30 across"
    assert plate_l.screw[2].c.center.y - plate_l.screw[1].c.center.y == 180 mm, "+-90 up"
    assert plate_l.screw[0].c.diameter == 5.5 mm, "5.5 mm screw holes"
    assert len(plate_l.mortise.slot) == 2 and len(arm_l.tenons.gap) == 3, "two tenons"
    assert arm_l.bar.c.diameter == 33 mm, "33 mm bar hole"
    assert arm_l.bar.c.center.x - arm_l.root_bar.bb.left == 120 mm, "bar 120 mm from the wall"
    assert arm_l.end.diameter == 60 mm, "60 mm round end"
    assert (arm_l.end.diameter - arm_l.bar.c.diameter) / 2 >= 10 mm, "10 mm of ply round the bar"
    assert distance(arm_l.label, arm_l.bar) >= 3 mm, "label clear of the bar hole"
    assert distance(arm_l.label, arm_l.tenons) >= 3 mm, "label clear of the tenon gaps"
    assert span == 600 mm, "600 apart"
}
