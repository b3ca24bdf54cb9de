# Request: a freestanding screen to hide the wheelie bins on the patio, cut from 6 mm
# exterior ply. The panel is 560 x 380 mm with R15 corners, a solid border 25 mm wide all
# round, and inside it a pattern of leaf-shaped openings, each 32 x 14 mm (an ellipse), tilted
# +35 deg and -35 deg in turn along a row: 9 rows 34 mm apart, the rows alternately 12 and
# 11 leaves at 40 mm pitch (the 11-leaf rows shifted half a pitch), the pattern centred across
# and kept at least 8 mm clear of the halving slots. The panel stands in two feet, 200 mm
# long (front to back) and 60 mm tall with R10 top corners, crossing it 100 mm from each end:
# cross-halving slots 30 mm deep up from the panel's bottom edge and 30 mm deep down from the
# middle of each foot's top, 0.2 mm clearance on the 6 mm ply.

import "std/joints.aidl"

units mm
thickness 6 mm

T = 6 mm
PW = 560 mm
PH = 380 mm
BORDER = 25 mm
ROWS = 9
ROW_PITCH = 34 mm
COL_PITCH = 40 mm
SLOT_X = PW / 2 - 100 mm
HALVE = 30 mm
Y0 = 7.5 mm - 4 * ROW_PITCH

def foot() -> solid {
    body = RoundedRectangle(center=(0, 0), width=200, height=60, corner_radii=[10, 10, 0, 0])
    notch = cross_halving(depth=HALVE, thickness=T, clearance=0.2 mm, cx=0, cy=30)
}

assembly screen {
    solid panel {
        body = RoundedRectangle(center=(0, 0), width=PW, height=PH, corner_radius=15)
        left_slot = cross_halving(depth=HALVE, thickness=T, clearance=0.2 mm, rotation=180,
                                  cx=-SLOT_X, cy=-PH / 2)
        right_slot = cross_halving(depth=HALVE, thickness=T, clearance=0.2 mm, rotation=180,
                                   cx=SLOT_X, cy=-PH / 2)
        hole leaves {
            for r in range(ROWS) {
                for c in range(12 - r % 2) {
                    e = Ellipse(center=(-5.5 * COL_PITCH + c * COL_PITCH + (r % 2) * COL_PITCH / 2,
                                        Y0 + r * ROW_PITCH),
                                rx=16, ry=7, rotation=(35 if c % 2 == 0 else -35))
                }
            }
        }
    }
    Place(panel, position=(0, T / 2, PH / 2), face="front", up="up")

    for i in range(2) {
        feet = foot()
        Below(feet, panel, gap=10 mm)
        feet.body.center.x == -110 mm + i * 220 mm
        Place(feet, position=((2 * i - 1) * SLOT_X - T / 2, 0, 30), face="right", up="up")
    }

    assert panel.body.bb.width == 560 mm and panel.body.bb.height == 380 mm, "560 x 380"
    assert panel.leaves.bb.left - panel.body.bb.left >= 25 mm, "25 mm border left"
    assert panel.body.bb.right - panel.leaves.bb.right >= 25 mm, "25 mm border right"
    assert panel.body.bb.top - panel.leaves.bb.top >= 25 mm, "25 mm border top"
    assert panel.leaves.bb.bottom - panel.left_slot.cut.bb.top >= 8 mm, "8 mm clear of the slots"
    assert abs((panel.leaves.bb.left - panel.body.bb.left) - (panel.body.bb.right - panel.leaves.bb.right)) < 0.01 mm,
        "pattern centred across"
    assert len(panel.leaves.e) == 9, "9 rows"
    assert sum([len(row) for row in panel.leaves.e]) == 5 * 12 + 4 * 11, "12 and 11 in turn"
    assert panel.leaves.e[0][1].center.x - panel.leaves.e[0][0].center.x == 40 mm, "40 mm pitch"
    assert panel.leaves.e[1][0].center.y - panel.leaves.e[0][0].center.y == 34 mm, "rows 34 apart"
    assert panel.left_slot.cut.bb.height == 30 mm, "30 mm deep in the panel"
    assert panel.left_slot.cut.bb.center_x - panel.body.bb.left == 100 mm, "100 mm from the end"
    assert panel.body.bb.right - panel.right_slot.cut.bb.center_x == 100 mm, "100 mm from the end"
    assert feet[0].body.bb.width == 200 mm and feet[0].body.bb.height == 60 mm, "feet 200 x 60"
    assert feet[0].notch.cut.bb.height == 30 mm, "30 mm deep in the foot"
    assert feet[0].notch.cut.bb.height + panel.left_slot.cut.bb.height == 60 mm,
        "the two halvings add up to the foot's height"
}
