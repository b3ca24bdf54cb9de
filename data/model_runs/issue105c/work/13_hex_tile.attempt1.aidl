# Hexagonal tile: 100 mm across flats, with a 6-hole bolt circle (PCD 60 mm, 5 mm
# holes, first hole on +x) and a 20 mm centre hole.
import stdlib.shapes
solid tile {
    body = RegularPolygon(center=(0, 0), across_flats=100, sides=6)
    bolts = bolt_circle(count=6, pcd=60, hole_d=5)
    bolts.bb.center == body.center
    hole centre {
        c = Circle(center=(0, 0), diameter=20)
    }
    Concentric(centre.c, body)
}
