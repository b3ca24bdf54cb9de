# The studio's form of examples/generators/flex_box.aidl: its arguments as params whose
# ranges follow each other (docs/studio.md, "Forms that cannot fail").
import "std/boxes.aidl"

# How the arguments depend on each other: the corner radius is at least twice the thickness
# (once, measured inside) plus the clearance and at most half the width and the length less
# 0.5 mm (a straight side shorter than 1 mm puts the flex cuts of two corners closer than a
# wall: W0507 at thickness 1.5 mm, clearance 1 mm, radius 33.9 mm); the
# wall between the base and the lid is at least 17 mm tall (its flex cuts are 15 mm long: a
# lower wall is cut apart, W0510); the clearance is under the thickness.
param thickness = 3 mm, min = 1 mm, max = 12 mm, step = 0.5 mm
param clearance = 0.3 mm, min = 0 mm, max = thickness / 2, step = 0.05 mm
param outside = true
param length = 120 mm, min = 2 * ((2 * thickness if outside else thickness) + clearance) + 10 mm, max = 480 mm, step = 1 mm
param width = 80 mm, min = 2 * ((2 * thickness if outside else thickness) + clearance) + 10 mm, max = 320 mm, step = 0.5 mm
param height = 50 mm, min = (2 if outside else 0) * thickness + 17 mm, max = 200 mm, step = 0.5 mm
param radius = 20 mm, min = (2 * thickness if outside else thickness) + clearance, max = min(length, width) / 2 - 0.5 mm, step = 0.2 mm

thickness thickness
kerf 0.15 mm

assembly round_box {
    box = flex_box(length=length, width=width, height=height, radius=radius,
                   thickness=thickness, clearance=clearance, outside=outside)
}
