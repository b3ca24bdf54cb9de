# Request: a drying rack for four baby bottles, cut from 5 mm clear acrylic.
# - A 220 x 200 base (10 mm corners) with 16 drain holes of 6 mm on a 50 mm grid, and
#   "BOTTLES" engraved along the front edge.
# - Four posts on a 2 x 2 grid at 100 mm pitch each way, centred on the base. Each post is two
#   44 mm wide blades standing 150 mm above the base with 15 mm rounded top corners, slotted
#   into each other crosswise (cross halving: one slot from the top, one from the bottom).
# - Each blade is glued into the base with two 10 mm tabs through mortises.

import "std/joints.aidl"

units mm
thickness 5 mm

T = 5 mm
BLADE_W = 44 mm
BLADE_H = 150 mm        # above the base
PITCH = 100 mm
PX = [-50, 50, -50, 50]
PY = [-50, -50, 50, 50]

# a blade: tab tips on y = 0, the blade above them
def blade_top_slot() -> solid {
    body = RoundedRectangle(center=(0, (BLADE_H + T) / 2), width=BLADE_W, height=BLADE_H + T,
                            corner_radii=[15, 15, 0, 0])
    tabs = tab_and_slot(part="tab", length=BLADE_W, thickness=T, tabs=2, tab=10 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    halving = cross_halving(depth=(BLADE_H + T) / 2 - 2.5 mm, thickness=T, cx=0 mm,
                            cy=BLADE_H + T)
}

def blade_bottom_slot() -> solid {
    body = RoundedRectangle(center=(0, (BLADE_H + T) / 2), width=BLADE_W, height=BLADE_H + T,
                            corner_radii=[15, 15, 0, 0])
    tabs = tab_and_slot(part="tab", length=BLADE_W, thickness=T, tabs=2, tab=10 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    halving = cross_halving(depth=(BLADE_H + T) / 2 + 2.5 mm, thickness=T, rotation=180 deg,
                            cx=0 mm, cy=0 mm)
}

assembly rack {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=220, height=200, corner_radius=10)
        hole drain {
            c = Circle(center=(-75, -75), diameter=6)
        }
        drains = GridPattern(drain, 4, 4, (50, 50))
        for i in range(4) {
            along_x = tab_and_slot(part="slot", length=BLADE_W, thickness=T, tabs=2, tab=10 mm,
                                   screw=0, cx=PX[i], cy=PY[i])
            along_y = tab_and_slot(part="slot", length=BLADE_W, thickness=T, tabs=2, tab=10 mm,
                                   screw=0, rotation=90 deg, cx=PX[i], cy=PY[i])
        }
        drawing label {
            t = Text("BOTTLES", position=(0, -92), size=8)
        }
    }

    for i in range(4) {
        a = blade_top_slot()
        b = blade_bottom_slot()
        # on the sheet: the blades in a row right of the base
        a.bb.left == base.bb.right + 10 + i * 2 * (BLADE_W + 6)
        b.bb.left == a.bb.right + 6
        AlignBottom(a, base)
        AlignBottom(b, base)
        # assembled: a along x, b along y, crossing at the post's centre
        Place(a, rotation=(90 deg, 0, 0), position=(PX[i], PY[i] + T / 2, 0))
        Place(b, rotation=(90 deg, 0, 90 deg), position=(PX[i] - T / 2, PY[i], 0))
    }

    # the request's numbers
    assert len(a) == 4 and len(b) == 4, "four posts of two blades"
    assert base.body.bb.width == 220 mm and base.body.bb.height == 200 mm, "base 220 x 200"
    assert len(base.drains) == 16, "16 drain holes"
    assert base.drains[1].c.center.x - base.drains[0].c.center.x == 50 mm, "50 mm drain grid"
    assert base.along_x[1].bb.center_x - base.along_x[0].bb.center_x == 100 mm, "100 mm pitch in x"
    assert base.along_x[2].bb.center_y - base.along_x[0].bb.center_y == 100 mm, "100 mm pitch in y"
    assert a[0].body.bb.height - T == 150 mm, "blades stand 150 mm above the base"
    assert a[0].body.bb.width == 44 mm, "blades 44 mm wide"
    assert a[0].halving.cut.bb.height + b[0].halving.cut.bb.height == a[0].body.bb.height,
        "the two halving slots add up to the blades' overlap"
    # the crossing blade must not run through a tab's mortise
    assert base.along_x[0].slot[1].bb.left - base.along_x[0].bb.center_x > T / 2,
        "mortises clear of the crossing blade"
}
