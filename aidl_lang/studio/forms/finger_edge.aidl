# The studio's form of examples/generators/finger_edge.aidl: its arguments as params whose
# ranges follow each other (docs/studio.md, "Forms that cannot fail").
import "std/joints.aidl"

# A base and a wall joined by fingers along one edge `length` long: the edge is cut into an
# odd number of fingers at least `finger` wide (at least 3), so `finger` is at most a third of
# the edge, and at least the thickness (a finger narrower than the sheet breaks off).
param thickness = 3 mm, min = 1 mm, max = 12 mm, step = 0.5 mm
param length = 100 mm, min = max(20 mm, 9 * thickness), max = 400 mm, step = 1 mm
param finger = 10 mm, min = max(2 mm, thickness), max = length / 3, step = 0.5 mm
param depth = 60 mm, min = thickness + 10 mm, max = 300 mm, step = 1 mm   # the base's
param height = 40 mm, min = thickness + 10 mm, max = 300 mm, step = 1 mm  # the wall's

thickness thickness

assembly corner {
    solid base {
        body = Rectangle(center=(0, 0), width=length, height=depth)
        fingers = finger_edge(length=length, thickness=thickness, finger=finger, start="tab",
                              cy=depth / 2)
    }
    solid wall {
        body = Rectangle(center=(0, depth / 2 + 10 mm + height / 2), width=length, height=height)
        fingers = finger_edge(length=length, thickness=thickness, finger=finger, start="gap",
                              rotation=180 deg, cy=depth / 2 + 10 mm)
    }
    # the wall stood up along the base's back edge, over its last sheet's thickness
    Place(wall, rotation=(90 deg, 0, 0), position=(0, depth / 2, -(depth / 2 + 10 mm)))
}
