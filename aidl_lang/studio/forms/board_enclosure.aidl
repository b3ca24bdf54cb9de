# The studio's form of examples/generators/board_enclosure.aidl: its arguments as params whose
# ranges follow each other (docs/studio.md, "Forms that cannot fail").
import "std/enclosures.aidl"

# How the arguments depend on each other: the board sits on the standoffs (1.6 mm thick) and
# its tallest port (8 mm) stays under the lid, so the box is at least standoff + 9.6 mm deep.
# With 11 mm the port's wall to the lid stays 0.5 mm (checked across the sliders: thinner
# past standoff + 10.6 mm), and a board under 53 mm tall leaves the standoff holes off the bottom.
param width = 85 mm, min = 60 mm, max = 340 mm, step = 0.5 mm
param height = 56 mm, min = 53 mm, max = 224 mm, step = 0.5 mm
param thickness = 3 mm, min = 1 mm, max = 12 mm, step = 0.5 mm
param clearance = 2 mm, min = 0 mm, max = 8 mm, step = 0.05 mm
param hole_d = 3.2 mm, min = 0.8 mm, max = 6 mm, step = 0.05 mm
param standoff = 5 mm, min = 1.25 mm, max = 20 mm, step = 0.05 mm
param depth = 25 mm, min = standoff + 11 mm, max = 100 mm, step = 0.2 mm
param vent = "hex"
param finger = 10 mm, min = 2.5 mm, max = 40 mm, step = 0.1 mm

thickness thickness

assembly case {
    box = board_enclosure(width=width, height=height, depth=depth, thickness=thickness,
                          clearance=clearance, hole_d=hole_d, standoff=standoff,
                          ports=[["front", 20, 10, 4], ["right", 28, 14, 8]], vent=vent,
                          finger=finger)
}
