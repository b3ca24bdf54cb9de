import "std/joints.aidl"
thickness 3 mm
assembly box {
    k = finger_box(length=100 mm, depth=60 mm, height=40 mm, thickness=3 mm, finger=10 mm)
}
