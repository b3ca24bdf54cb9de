# A regular hexagon with sides of 15.5 mm and a 10.25 mm hole through the centre, 2.5 mm thick.

param side = 15.5 mm
param hole_d = 10.25 mm

thickness 2.5 mm

solid hex {
    # for a regular hexagon the centre-to-vertex radius equals the side
    body = RegularPolygon(center=(0, 0), radius=side, sides=6)
    Fixed(body)
    hole bore {
        c = Circle(center=(0, 0), diameter=hole_d)
    }
    Concentric(bore.c, body)
}
