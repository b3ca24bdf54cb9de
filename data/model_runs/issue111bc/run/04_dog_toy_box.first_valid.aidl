# Request (pets): "A toy box for our dog Biscuit, 6 mm birch ply, finger-jointed (30 mm
# fingers), open top, 450 x 320 x 280 mm outside. The front dips 80 mm in a 200 mm wide U
# (40 mm radius at the bottom corners) so she can reach in and pull toys out. 'BISCUIT'
# engraved filled on the front in 50 mm bold capitals, centred 150 mm below the top edge,
# with a filled bone (60 x 24 mm) each side of the name, 165 mm from the middle. A 100 x 30
# mm hand slot in each end, its centre 50 mm below the top edge."

import "std/joints.aidl"

thickness 6 mm

param box_l = 450 mm, min = 300 mm, max = 600 mm
param box_d = 320 mm, min = 200 mm, max = 400 mm
param box_h = 280 mm, min = 200 mm, max = 400 mm

assembly toy_box {
    box = finger_box(length=box_l, depth=box_d, height=box_h, thickness=6 mm, finger=30 mm,
                     closed=false)

    # the front's dip
    hole dip {
        d = RoundedRectangle(center=(0, 0), width=200, height=81,
                             corner_radii=[0, 0, 40, 40])
    }
    AlignCenterX(dip, box.front)
    dip.d.bb.top == box.front.bb.top + 1 mm
    CutInto(dip, box.front)

    # the name and two bones
    drawing label {
        name = Text("BISCUIT", position=(0, 0), size=50, font="sans:Bold", valign="middle",
                    fill=true)
        for side in [-1, 1] {
            bar = Rectangle(center=(side * 165, 0), width=44, height=10, fill=true)
            k1 = Circle(center=(side * 165 - 22, 6), radius=6, fill=true)
            k2 = Circle(center=(side * 165 - 22, -6), radius=6, fill=true)
            k3 = Circle(center=(side * 165 + 22, 6), radius=6, fill=true)
            k4 = Circle(center=(side * 165 + 22, -6), radius=6, fill=true)
        }
    }
    AlignCenterX(label, box.front)
    label.name.position.y == box.front.bb.top - 150 mm
    CutInto(label, box.front)

    # hand slots: the sides lie with their top edge outward (left: at -x, right: at +x)
    hole grip_l { s = Slot(center=(0, 0), length=100, width=30, rotation=90 deg) }
    AlignCenterY(grip_l, box.left)
    grip_l.s.center.x == box.left.bb.left + 50 mm
    CutInto(grip_l, box.left)
    hole grip_r { s = Slot(center=(0, 0), length=100, width=30, rotation=90 deg) }
    AlignCenterY(grip_r, box.right)
    grip_r.s.center.x == box.right.bb.right - 50 mm
    CutInto(grip_r, box.right)

    # the request's numbers
    assert box.front.bb.width == 450 mm, "450 long outside"
    assert box.left.bb.height == 320 mm, "320 deep outside"
    assert box.front.bb.height == 280 mm, "280 tall outside"
    assert box.front.bb.top - dip.d.bb.bottom == 80 mm, "dip 80 mm deep"
    assert dip.d.bb.width == 200 mm, "dip 200 mm wide"
    assert label.name.size == 50 mm, "50 mm letters"
    assert label.bar[1].center.x - label.name.position.x == 165 mm, "bones 165 from the middle"
    assert label.k4[1].bb.right - label.k1[1].bb.left == 56 mm, "bone 56 + ... wide"
    assert grip_l.s.length == 100 mm and grip_l.s.width == 30 mm, "100 x 30 slots"
}
