# Issue 73: a finger box and a hole cut into its lid: the box stays where finger_box puts
# it and the hole goes to the middle of the lid (before: the box was shifted 70 mm down to
# meet the hole halfway).
import "std/joints.aidl"

thickness 3 mm

assembly kit {
    box = finger_box(length=80 mm, depth=60 mm, height=40 mm, thickness=3 mm)
    hole lid_hole { c = Circle(center=(0, 0), diameter=20) }
    CenterInside(lid_hole, box.lid)
    CutInto(lid_hole, box.lid)
}
