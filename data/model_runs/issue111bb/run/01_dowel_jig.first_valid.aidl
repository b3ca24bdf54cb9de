# Request (workshop): a dowel drilling jig for the edges of 18 mm boards, cut from 6 mm birch ply.
# Top plate 120 x 60 mm that rests on the board's edge, with three drill guide holes of 6, 8 and
# 10 mm in a row 32 mm apart, their centres 9 mm from the fence's inner face (the middle of an
# 18 mm board). Fence 120 x 40 mm that hangs down against the board's face, glued to the top
# plate's long edge with two 15 mm tenons in mortises, flush with the plate's edge. Engrave the
# bit size next to each hole ("6", "8", "10") and "DOWEL JIG 18 mm" on the plate; the fence gets
# two 5 mm holes for clamping a stop block.

import "std/joints.aidl"

thickness 6 mm

param t = 6 mm, min = 3 mm, max = 9 mm
param board = 18 mm, min = 12 mm, max = 25 mm
param pitch = 32 mm, min = 25 mm, max = 40 mm

assembly dowel_jig {
    solid plate {
        body = Rectangle(center=(0, 0), width=120, height=60)
        # mortises for the fence's tenons, flush with the plate's bottom (long) edge
        mort = tab_and_slot(part="slot", length=120 mm, thickness=t, tabs=2, tab=15 mm,
                            screw=0, cx=0 mm, cy=-30 mm + t / 2)
        hole guides {
            g6 = Circle(center=(-pitch, -30 + t + board / 2), diameter=6)
            g8 = Circle(center=(0, -30 + t + board / 2), diameter=8)
            g10 = Circle(center=(pitch, -30 + t + board / 2), diameter=10)
        }
        drawing labels {
            l6 = Text("6", (-pitch, -2), size=5)
            l8 = Text("8", (0, -2), size=5)
            l10 = Text("10", (pitch, -2), size=5)
        }
        drawing title {
            name = Text("DOWEL JIG 18 mm", (0, 15), size=6)
        }
    }

    solid fence {
        # 40 mm below the plate plus the tenons standing t through it
        body = Rectangle(center=(0, 0), width=120, height=40 + t)
        tenons = tab_and_slot(part="tab", length=120 mm, thickness=t, tabs=2, tab=15 mm,
                              screw=0, cx=0 mm, cy=(40 + t) / 2)
        hole clamp {
            a = Circle(center=(-45, -6), diameter=5)
            b = Circle(center=(45, -6), diameter=5)
        }
    }

    Below(fence, plate, gap=10)
    AlignCenterX(fence, plate)
    # fence hangs under the plate's bottom edge: local y -> z, tenon tips flush with the plate top
    Place(fence, rotation=(90 deg, 0, 0), position=(0, -30 + t, t - (40 + t) / 2))

    # the request's numbers
    assert plate.body.bb.width == 120 mm and plate.body.bb.height == 60 mm, "plate 120 x 60"
    assert fence.body.bb.width == 120 mm, "fence 120 long"
    assert fence.body.bb.height - t == 40 mm, "fence hangs 40 below the plate"
    assert plate.guides.g6.diameter == 6 mm and plate.guides.g8.diameter == 8 mm and
        plate.guides.g10.diameter == 10 mm, "bit sizes 6, 8, 10"
    assert plate.guides.g8.center.x - plate.guides.g6.center.x == 32 mm, "32 mm apart"
    assert plate.guides.g10.center.x - plate.guides.g8.center.x == 32 mm, "32 mm apart"
    assert plate.guides.g8.center.y - (plate.body.bb.bottom + t) == 9 mm,
        "holes 9 mm from the fence's inner face"
    assert fence.clamp.a.diameter == 5 mm, "5 mm clamp holes"
}
