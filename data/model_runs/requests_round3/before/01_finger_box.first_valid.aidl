# A closed finger-jointed box, 80 x 80 x 50 mm outside, 3 mm plywood,
# with a 20 mm round hole in the middle of the lid.
import "std/joints.aidl"

param L = 80 mm   # outside length (x)
param D = 80 mm   # outside depth (y)
param H = 50 mm   # outside height
param t = 3 mm
param hole_d = 20 mm

thickness 3 mm

assembly box {
    k = finger_box(length=L, depth=D, height=H, thickness=t, finger=10 mm, closed=true)
    hole lid_hole {
        c = Circle(center=(0, 0), diameter=hole_d)
    }
    CenterInside(lid_hole, k.lid)
}
