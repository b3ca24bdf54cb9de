# The studio's form of examples/generators/tool_holder.aidl: its arguments as params whose
# ranges follow each other (docs/studio.md, "Forms that cannot fail").
import "std/stands.aidl"

# How the arguments depend on each other: the holes are 4 mm apart and clear of the joints, so
# the box is at least cols x (hole + 4 mm) long and rows x (hole + 4 mm) deep inside.
param thickness = 3 mm, min = 1 mm, max = 12 mm, step = 0.5 mm
param outside = true
param rows = 2, min = 1, max = 12, step = 1
param cols = 3, min = 1, max = 12, step = 1
param hole = 16 mm, min = 4 mm, max = 64 mm, step = 0.1 mm
param length = 100 mm, min = cols * (hole + 4 mm) + (2 * thickness if outside else 0 mm) + 0.5 mm, max = max(400 mm, 2 * cols * (hole + 4 mm) + 4 * thickness), step = 1 mm
param depth = 70 mm, min = rows * (hole + 4 mm) + (2 * thickness if outside else 0 mm) + 0.5 mm, max = max(280 mm, 2 * rows * (hole + 4 mm) + 4 * thickness), step = 0.5 mm
param height = 90 mm, min = 22.5 mm, max = 360 mm, step = 0.5 mm
param finger = 10 mm, min = 2.5 mm, max = 40 mm, step = 0.1 mm

thickness thickness

assembly desk {
    pens = tool_holder(length=length, depth=depth, height=height, thickness=thickness,
                       finger=finger, rows=rows, cols=cols, hole=hole, outside=outside)
}
