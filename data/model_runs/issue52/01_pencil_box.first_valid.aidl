# A pencil box with a sliding lid, 200 x 70 x 50 mm outside, 3 mm plywood.
import "std/boxes.aidl"

units mm
thickness 3 mm
kerf 0.15 mm

param length = 200 mm
param width = 70 mm
param height = 50 mm

assembly pencil_box {
    box = sliding_lid_box(length=length, width=width, height=height, thickness=3 mm,
                          finger=10 mm, clearance=0.3 mm, outside=true)
}
