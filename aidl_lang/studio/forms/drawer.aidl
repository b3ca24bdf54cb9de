# The studio's form of examples/generators/drawer.aidl: its arguments as params whose ranges
# follow each other (docs/studio.md, "Forms that cannot fail").
import "std/boxes.aidl"

# How the arguments depend on each other: the drawer is longer, deeper and taller than four
# thicknesses inside a carcass of two more (one more at the open front) and the clearances, so
# the carcass's outer size (outside) or the space inside it has a minimum that grows with the
# thickness; the clearance is under the thickness.
param thickness = 3 mm, min = 1 mm, max = 12 mm, step = 0.5 mm
param clearance = 0.3 mm, min = 0 mm, max = min(1.2 mm, thickness - 0.05 mm), step = 0.05 mm
param outside = false
param length = 150 mm, min = max(37 mm, (6 if outside else 4) * thickness + 2 * clearance + 1 mm), max = 600 mm, step = 1 mm
param depth = 120 mm, min = max(30 mm, (5 if outside else 4) * thickness + clearance + 1 mm), max = 480 mm, step = 1 mm
param height = 60 mm, min = max(15 mm, (6 if outside else 4) * thickness + clearance + 1 mm), max = 240 mm, step = 0.5 mm
param finger = 10 mm, min = 2.5 mm, max = 40 mm, step = 0.1 mm
thickness thickness
kerf 0.15 mm

assembly desk_drawer {
    unit = drawer(length=length, depth=depth, height=height, thickness=thickness, finger=finger,
                  clearance=clearance, outside=outside)
}
