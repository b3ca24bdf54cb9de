# Request (kitchen): a rack that holds sous-vide bags upright and apart in the water
# bath, cut from 4 mm clear acrylic. Five divider plates 150 mm wide x 130 mm tall,
# top corners rounded 10 mm, each with three 25 mm flow holes (45 mm apart, centres
# 60 mm up) and a 60 x 20 mm lifting slot centred 110 mm up. The plates stand 50 mm apart
# on two base rails 260 mm long x 25 mm tall, 90 mm apart (45 mm either side of the
# plates' centre line). Cross halvings: each plate slotted 12.5 mm up from its bottom edge
# where the rails cross, each rail slotted 12.5 mm down from its top edge at every plate,
# slots 4.2 mm wide (0.2 mm clearance). "SOUS VIDE" engraved (7 mm, single stroke) on
# each rail under its middle slot.

units mm
thickness 4 mm
import "std/joints.aidl"

T = 4 mm
PLATES = 5
PITCH = 50 mm
RAIL_X = 45 mm

def divider() -> solid {
    body = RoundedRectangle(bottom_left=(-75, 0), width=150, height=130,
                            corner_radii=[10, 10, 0, 0])
    hole flow {
        for k in range(3) {
            c = Circle(center=((k - 1) * 45, 60), diameter=25)
        }
    }
    hole lift {
        s = Slot(center=(0, 110), length=60, width=20)
    }
    h_l = cross_halving(depth=12.5 mm, thickness=T, clearance=0.2 mm, rotation=180 deg,
                        cx=-RAIL_X, cy=0)
    h_r = cross_halving(depth=12.5 mm, thickness=T, clearance=0.2 mm, rotation=180 deg,
                        cx=RAIL_X, cy=0)
}

def base_rail() -> solid {
    body = Rectangle(bottom_left=(-130, 0), width=260, height=25)
    for k in range(PLATES) {
        s = cross_halving(depth=12.5 mm, thickness=T, clearance=0.2 mm,
                          cx=(k - 2) * PITCH, cy=25)
    }
    drawing label {
        t = Text("SOUS VIDE", position=(0, 3), size=7)
    }
}

assembly sous_vide_rack {
    for i in range(PLATES) {
        plate = divider()
        plate.bb.center == (i * 160 mm, 65 mm)
        # standing across the bath, 50 mm apart
        Place(plate, position=(0, (i - 2) * PITCH + T / 2, 0), face="front", up="up")
    }
    for j in range(2) {
        rail = base_rail()
        rail.bb.center == (140 mm + j * 280 mm, -30 mm)
        # on edge along the bath, 45 mm either side of the centre line
        Place(rail, position=((2 * j - 1) * RAIL_X - T / 2, 0, 0), face="right", up="up")
    }

    assert len(plate) == 5, "five plates"
    assert len(rail) == 2, "two rails"
    assert plate[0].body.bb.width == 150 mm and plate[0].body.bb.height == 130 mm, "plate size"
    assert rail[0].body.bb.width == 260 mm and rail[0].body.bb.height == 25 mm, "rail size"
    assert rail[0].s[1].cx - rail[0].s[0].cx == 50 mm, "plates 50 apart"
    assert plate[0].h_r.cx - plate[0].h_l.cx == 90 mm, "rails 90 apart"
    assert plate[0].h_l.depth + rail[0].s[0].depth == 25 mm, "halvings meet"
    assert plate[0].flow.c[1].center.x - plate[0].flow.c[0].center.x == 45 mm, "flow holes 45 apart"
    assert plate[0].flow.c[0].center.y - plate[0].body.bb.bottom == 60 mm, "flow holes 60 up"
    assert plate[0].lift.s.center.y - plate[0].body.bb.bottom == 110 mm, "lift slot 110 up"
    assert rail[0].label.bb.top <= rail[0].body.bb.top - 12.5 mm - 1 mm, "label under the slots"
}
