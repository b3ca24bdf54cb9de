# The studio's form of examples/generators/hinged_box.aidl: its arguments as params whose
# ranges follow each other (docs/studio.md, "Forms that cannot fail").
import "std/boxes.aidl"

# How the arguments depend on each other: the hinge's lobe is b = sqrt(p^2 + t^2) + clearance +
# 2/3 t (at least 1.2 mm) across (p: the pin, or the thickness when the pin is 0); the back wall's fingers are at
# least b wide and at least three of them fit; the box is wider than b and longer than its walls.
param thickness = 3 mm, min = 1 mm, max = 12 mm, step = 0.5 mm
param clearance = 0.3 mm, min = 0 mm, max = thickness / 2, step = 0.05 mm
param outside = true
param pin = 0 mm, min = 0 mm, max = 20 mm, step = 0.5 mm  # 0: as thick as the sheet
param finger = 10 mm, min = sqrt((pin if pin > 0 mm else thickness) * (pin if pin > 0 mm else thickness) + thickness * thickness) + clearance + 2 * max(thickness / 3, 0.6 mm), max = 40 mm, step = 0.1 mm
param length = 140 mm, min = 6 * thickness + 2 * clearance + 20 mm, max = 560 mm, step = 1 mm
param width = 90 mm, min = 2 * finger + 2 * thickness, max = 360 mm, step = 0.5 mm
param height = 60 mm, min = 3 * finger + (3 if outside else 1) * thickness + 1 mm, max = 240 mm, step = 0.5 mm

thickness thickness
kerf 0.15 mm

assembly keepsake {
    box = hinged_box(length=length, width=width, height=height, thickness=thickness,
                     finger=finger, pin=pin, clearance=clearance, outside=outside)
}
