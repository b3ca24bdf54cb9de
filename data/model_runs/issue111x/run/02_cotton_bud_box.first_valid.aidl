# Bathroom: an open-top box for cotton buds, 90 mm long x 60 mm deep x 70 mm tall outside,
# 3 mm plywood, finger joints 10 mm; "COTTON BUDS" engraved 7 mm tall centred on the front;
# a 30 mm finger scoop (a half circle) in the middle of the front's top edge.

import "std/joints.aidl"

thickness 3 mm

assembly kit {
    box = finger_box(length=90 mm, depth=60 mm, height=70 mm, thickness=3 mm, finger=10 mm,
                     closed=false)

    drawing label {
        t = Text("COTTON BUDS", (0, 0), size=7, valign="middle")
    }
    CenterInside(label, box.front)
    CutInto(label, box.front)

    hole scoop {
        c = Circle(center=(0, 0), diameter=30)
    }
    AlignCenterX(scoop, box.front)
    scoop.c.center.y == box.front.bb.top
    CutInto(scoop, box.front)
}

assert kit.box.front.bb.width == 90 mm, "90 mm long outside"
assert kit.box.front.bb.height == 70 mm, "70 mm tall outside"
assert kit.box.left.bb.height == 60 mm, "60 mm deep outside"
assert kit.box.left.bb.width == 70 mm, "sides 70 mm tall"
assert kit.scoop.c.diameter == 30 mm, "30 mm scoop"
