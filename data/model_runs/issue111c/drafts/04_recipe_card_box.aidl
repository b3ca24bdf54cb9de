# Recipe card box for 6 x 4 in cards: an open-top finger-jointed box in 3 mm
# plywood whose space inside is 160 x 110 mm and 80 mm high, 10 mm fingers; a
# 30 mm thumb notch (a half circle) in the middle of the front's top edge.
import "std/joints.aidl"

thickness 3 mm

assembly kit {
    box = finger_box(length=160 mm, depth=110 mm, height=80 mm, thickness=3 mm,
                     finger=10 mm, closed=false, outside=false)
    hole thumb {
        c = Circle(center=(0, 0), diameter=30)
    }
    AlignCenterX(thumb, box.front)
    thumb.c.center.y == box.front.bb.top
    CutInto(thumb, box.front)
}

# outer sizes: two thicknesses more each way, one more in height (open top)
assert kit.box.front.bb.width == 166 mm, "front spans 160 mm inside + 2 x 3 mm"
assert kit.box.front.bb.height == 83 mm, "80 mm inside + 3 mm bottom"
assert kit.box.left.bb.width == 116 mm or kit.box.left.bb.height == 116 mm, "sides span 110 mm inside"
assert kit.thumb.c.diameter == 30 mm, "30 mm notch"
