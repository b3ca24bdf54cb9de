# Pets: dog-treat box in 3 mm plywood, a closed finger-jointed box 160 x 110 x 90 mm outside
# (10 mm fingers). On the lid "TREATS" in sans Bold letters 18 mm tall cut through as a
# stencil, centred. In the front a bone-shaped window: a 50 x 10 mm bar with two 12 mm
# circles at each end (their centres 25 mm either side of the middle and 5 mm above and
# below the bar's axis), centred 50 mm above the box's bottom edge.

import "std/joints.aidl"

thickness 3 mm

assembly kit {
    box = finger_box(length=160 mm, depth=110 mm, height=90 mm, thickness=3 mm, finger=10 mm)

    hole word {
        t = Text("TREATS", (0, 0), size=18, valign="middle", font="sans:Bold", stencil=true)
    }
    CenterInside(word, box.lid)
    CutInto(word, box.lid)

    hole bone {
        bar = Rectangle(center=(0, 0), width=50, height=10)
        e1 = Circle(center=(-25, 5), diameter=12)
        e2 = Circle(center=(-25, -5), diameter=12)
        e3 = Circle(center=(25, 5), diameter=12)
        e4 = Circle(center=(25, -5), diameter=12)
        AllowOverlap(e1, e2, e3, e4)  # one bone-shaped opening, as meant
    }
    AlignCenterX(bone, box.front)
    bone.bar.center.y == box.front.bb.bottom + 50 mm
    CutInto(bone, box.front)

    assert box.front.bb.width == 160 mm, "160 long"
    assert box.front.bb.height == 90 mm, "90 tall"
    assert box.left.bb.height == 110 mm, "110 deep"
    assert word.t.size == 18 mm, "letters 18 mm"
    assert bone.bar.width == 50 mm and bone.e1.diameter == 12 mm, "bone sizes"
}
