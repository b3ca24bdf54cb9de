# The studio's form of examples/generators/sliding_lid_box.aidl: its arguments as params whose
# ranges follow each other (docs/studio.md, "Forms that cannot fail").
import "std/boxes.aidl"

# How the arguments depend on each other: the box is taller than five thicknesses and the
# clearance (outside), longer than six and wider than four thicknesses; the clearance is under
# the thickness.
param thickness = 3 mm, min = 1 mm, max = 12 mm, step = 0.5 mm
param clearance = 0.3 mm, min = 0 mm, max = thickness / 2, step = 0.05 mm
param outside = true
param length = 80 mm, min = (6 if outside else 2) * thickness + 10 mm, max = 320 mm, step = 0.5 mm
param width = 200 mm, min = (4 if outside else 2) * thickness + 10 mm, max = 800 mm, step = 2 mm
param height = 45 mm, min = (5 * thickness + clearance if outside else thickness) + 5 mm, max = 180 mm, step = 0.2 mm
param finger = 10 mm, min = 2.5 mm, max = 40 mm, step = 0.1 mm

thickness thickness
kerf 0.15 mm

assembly kit {
    box = sliding_lid_box(length=length, width=width, height=height, thickness=thickness,
                          finger=finger, clearance=clearance, outside=outside)
}
