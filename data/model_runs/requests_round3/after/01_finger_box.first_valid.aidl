# A closed finger-jointed box, 80 x 80 x 50 mm outside, 3 mm plywood,
# with a 20 mm round hole in the middle of the lid.
import "std/joints.aidl"

thickness 3 mm

assembly kit {
    box = finger_box(length=80 mm, depth=80 mm, height=50 mm, thickness=3 mm, closed=true)
    hole lid_hole { c = Circle(center=(0, 0), diameter=20) }
    CenterInside(lid_hole, box.lid)
    CutInto(lid_hole, box.lid)
}
