# A 100 x 60 mm mounting plate, 3 mm thick: a 20 mm bore in the centre, six M4
# clearance holes (4.5 mm) on a 40 mm bolt circle, and four 3.2 mm holes 6 mm
# in from the corners' edges.
import "std/shapes.aidl"

thickness 3 mm

solid plate {
    body = Rectangle(center=(0, 0), width=100, height=60)
    Fixed(body)
    hole bore { c = Circle(center=(0, 0), diameter=20) }
    Concentric(bore.c, body)
    bolts = bolt_circle(count=6, pcd=40 mm, hole_d=4.5 mm)
    Concentric(bolts.pitch, body)
    hole corner { c = Circle(center=(0, 0), diameter=3.2) }
    CornerPattern(corner, body, 6)
}
