# Request: one tray of a stacking garden wormery, from 6 mm exterior ply: an open-top
# finger-jointed box 400 x 400 mm outside, 150 mm tall, 25 mm fingers. The bottom is a mesh
# for the worms to climb through: 14 x 14 holes of 10 mm on a 25 mm pitch, centred. Each
# side (left and right) has a hand hole 100 x 30 mm (rounded ends) running along the side,
# its top 25 mm below the rim. The front and back each have a row of 8 air holes of 10 mm,
# 40 mm apart, centred, their tops 30 mm below the rim; "WORMERY 1" is engraved on the
# front in 20 mm bold letters, 15 mm below the air holes.

import "std/joints.aidl"

units mm
thickness 6 mm

param size = 400 mm, min = 300, max = 500
param tall = 150 mm, min = 100, max = 200
param pitch = 25 mm, min = 20, max = 30

assembly wormery {
    box = finger_box(length=size, depth=size, height=tall, thickness=6 mm, finger=25 mm,
                     closed=false)

    hole mesh {
        for r in range(14) {
            for c in range(14) {
                h = Circle(center=(c * pitch, r * pitch), diameter=10)
            }
        }
    }
    CenterInside(mesh, box.bottom)
    CutInto(mesh, box.bottom)

    hole grip_l { s = Slot(center=(0, 0), length=100, width=30, rotation=90) }
    hole grip_r { s = Slot(center=(0, 0), length=100, width=30, rotation=90) }
    AlignCenterY(grip_l, box.left)
    AlignCenterY(grip_r, box.right)
    # a side lies with its top edge outward (the left's at -x, the right's at +x)
    grip_l.bb.left == box.left.bb.left + 25 mm
    grip_r.bb.right == box.right.bb.right - 25 mm
    CutInto(grip_l, box.left)
    CutInto(grip_r, box.right)

    def air_row() -> hole {
        for i in range(8) {
            a = Circle(center=(i * 40 mm, 0), diameter=10)
        }
    }
    air_f = air_row()
    air_b = air_row()
    AlignCenterX(air_f, box.front)
    AlignCenterX(air_b, box.back)
    air_f.bb.top == box.front.bb.top - 30 mm
    air_b.bb.top == box.back.bb.top - 30 mm
    CutInto(air_f, box.front)
    CutInto(air_b, box.back)

    drawing label {
        t = Text("WORMERY 1", position=(0, 0), size=20, font="sans:Bold", fill=true)
    }
    AlignCenterX(label, box.front)
    label.bb.top == air_f.bb.bottom - 15 mm
    CutInto(label, box.front)

    assert box.front.bb.width == 400 mm, "400 outside"
    assert box.front.bb.height == 150 mm, "150 tall"
    assert len(mesh.h) == 14 and len(mesh.h[0]) == 14, "14 x 14 mesh"
    assert mesh.h[0][1].center.x - mesh.h[0][0].center.x == 25 mm, "25 pitch"
    assert abs(mesh.bb.center_x - box.bottom.bb.center_x) < 0.01 mm, "mesh centred"
    assert len(air_f.a) == 8, "8 air holes"
    assert air_f.a[1].center.x - air_f.a[0].center.x == 40 mm, "40 apart"
    assert grip_l.s.length == 100 mm and grip_l.s.width == 30 mm, "hand hole 100 x 30"
    assert grip_l.bb.left - box.left.bb.left == 25 mm, "hand hole 25 below the rim"
    assert air_f.bb.bottom - label.bb.top == 15 mm, "label 15 under the air holes"
}
