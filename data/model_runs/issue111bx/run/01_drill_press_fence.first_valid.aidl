# Request: a drill-press fence with a sliding stop, cut from 6 mm birch ply. A base strip
# 400 x 60 mm lies on the drill-press table; two 8 mm wide, 40 mm long slots run across it
# (front to back) for the table's clamping bolts, their centres 60 mm in from each end. A fence
# face 400 mm long stands 50 mm tall on the base's back edge, glued into the base by four
# 20 mm tabs. A scale is engraved along the top of the fence face: a 5 mm tick every 10 mm
# from its left end, 10 mm ticks every 50 mm with the number under them (4 mm figures).
# A stop block 40 x 60 mm sits astride the fence: a 6.2 mm wide notch 30 mm deep up from its
# bottom edge, its corners rounded r3.

import "std/joints.aidl"

thickness 6 mm

param fence_len = 400 mm, min = 200 mm, max = 600 mm
param base_depth = 60 mm, min = 40 mm, max = 100 mm
param face_h = 50 mm, min = 30 mm, max = 80 mm
t = 6 mm

assembly fence {
    solid base {
        plate = Rectangle(center=(0, 0), width=fence_len, height=base_depth)
        hole clamp_slots {
            left = Slot(center=(-fence_len / 2 + 60, 0), length=40, width=8, rotation=90)
            right = Slot(center=(fence_len / 2 - 60, 0), length=40, width=8, rotation=90)
        }
        # the fence face's tabs go into slots along the back edge, t / 2 in from it
        mortises = tab_and_slot(part="slot", length=fence_len, thickness=t, tabs=4, tab=20 mm,
                                screw=0, cx=0 mm, cy=base_depth / 2 - t / 2)
    }

    solid face {
        # the face's bottom edge (the tabs' tips) on y = 0, the face above it
        board = Rectangle(bottom_left=(-fence_len / 2, 0), width=fence_len, height=face_h + t)
        tabs = tab_and_slot(part="tab", length=fence_len, thickness=t, tabs=4, tab=20 mm,
                            screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
        drawing scale {
            for i in range(1, 40) {
                tick = Line(start=(-fence_len / 2 + i * 10 mm, face_h + t),
                            length=(10 mm if i % 5 == 0 else 5 mm), angle=-90 deg)
            }
            for k in range(1, 8) {
                num = Text(str(k * 50), position=(-fence_len / 2 + k * 50 mm, face_h + t - 16),
                           size=4)
            }
        }
    }

    solid stop {
        block = RoundedRectangle(center=(0, 0), width=40, height=60, corner_radius=3)
        hole notch {
            n = Rectangle(bottom_left=(-3.1, -31), width=6.2, height=31)
        }
    }

    # flat: the base, the face stood on its back edge, the stop astride the face 100 mm along
    Place(base, position=(0, 0, 0))
    Place(face, rotation=(90 deg, 0, 0), position=(0, base_depth / 2, 0))
    Place(stop, rotation=(90 deg, 0, 90 deg), position=(-100, base_depth / 2 - t / 2, face_h + t))

    assert base.plate.bb.width == 400 mm, "base 400 long"
    assert base.plate.bb.height == 60 mm, "base 60 deep"
    assert base.clamp_slots.left.width == 8 mm, "clamp slots 8 wide"
    assert base.clamp_slots.left.center.x - base.plate.bb.left == 60 mm, "left slot 60 in"
    assert base.plate.bb.right - base.clamp_slots.right.center.x == 60 mm, "right slot 60 in"
    assert face.board.bb.height - t == 50 mm, "face 50 above the base"
    assert len(base.mortises.slot) == 4, "four tabs"
    assert stop.block.bb.width == 40 mm and stop.block.bb.height == 60 mm, "stop 40 x 60"
    assert stop.notch.n.bb.top - stop.block.bb.bottom == 30 mm, "notch 30 deep"
}
