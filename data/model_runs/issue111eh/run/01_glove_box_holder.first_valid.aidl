# Request (workshop): a wall holder for a box of nitrile gloves. The box is 230 x 125 x 62 mm
# and stands on its long edge with its big 230 x 125 face (where the gloves come out) to the
# front. 3 mm plywood, finger-jointed open-top sleeve: inside 236 long x 70 deep x 100 tall
# (3 mm play each end, 8 mm in depth for the screw heads behind it). The front has an oval
# opening 160 x 50 mm, its centre 60 mm above the inside floor, and "NITRILE GLOVES" engraved
# filled (sans bold, 8 mm) centred under it. The back hangs on two keyholes (8 mm head,
# 4 mm slot, 10 mm long, slot upward) 160 mm apart, centred, 75 mm above the inside floor.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 3 mm

param inner_l = 236 mm, min = 200 mm, max = 300 mm
param inner_d = 70 mm, min = 50 mm, max = 100 mm
param inner_h = 100 mm, min = 60 mm, max = 140 mm

assembly glove_holder {
    box = finger_box(length=inner_l, depth=inner_d, height=inner_h, thickness=3 mm,
                     finger=12 mm, closed=false, outside=false)

    # the oval opening in the front, centred, 60 mm above the inside floor
    hole opening {
        o = Ellipse(center=(0, 0), rx=80, ry=25)
    }
    AlignCenterX(opening, box.front)
    opening.o.center.y == box.front.bb.bottom + 3 mm + 60 mm
    CutInto(opening, box.front)

    drawing label {
        t = Text("NITRILE GLOVES", position=(0, 0), size=8, font="sans:Bold",
                 valign="middle", fill=true)
    }
    AlignCenterX(label, box.front)
    # halfway between the inside floor and the opening's bottom
    label.t.position.y == (box.front.bb.bottom + 3 mm + opening.o.bb.bottom) / 2
    CutInto(label, box.front)

    # two keyholes in the back, 160 apart, 75 above the inside floor
    kl = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg)
    kr = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg)
    kr.head_hole.center.x - kl.head_hole.center.x == 160 mm
    (kl.head_hole.center.x + kr.head_hole.center.x) / 2 == box.back.bb.center_x
    kl.head_hole.center.y == box.back.bb.bottom + 3 mm + 75 mm
    kr.head_hole.center.y == kl.head_hole.center.y
    CutInto(kl, box.back)
    CutInto(kr, box.back)

    # the request's numbers
    assert box.front.bb.width == 236 mm + 2 * 3 mm, "front is the inside length plus two walls"
    assert box.front.bb.height == 100 mm + 3 mm, "front is the inside height plus the floor"
    assert box.front.bb.width - 2 * 3 mm >= 230 mm + 4 mm, "the glove box slides in"
    assert opening.o.bb.width == 160 mm and opening.o.bb.height == 50 mm, "oval 160 x 50"
    assert opening.o.center.y - box.front.bb.bottom == 3 mm + 60 mm, "oval centre 60 above floor"
    assert opening.o.bb.top <= box.front.bb.top - 3 mm - 5 mm, "a rail stays above the oval"
    assert kr.head_hole.center.x - kl.head_hole.center.x == 160 mm, "keyholes 160 apart"
    assert kl.head_hole.center.y - box.back.bb.bottom == 3 mm + 75 mm, "keyholes 75 above floor"
    assert kl.slot.bb.top <= box.back.bb.top - 3 mm - 5 mm, "keyhole slot clear of the top"
    assert distance(label, opening) >= 2 mm, "label clear of the oval"
}
