# A regular hexagon with sides of 15.5 mm and a 10.25 mm hole through the centre, 2.5 mm thick.
thickness 2.5 mm

solid hex {
    body = RegularPolygon(center=(0, 0), side=15.5, sides=6)
    hole bore { c = Circle(center=(0, 0), diameter=10.25) }
    Concentric(bore.c, body)
}
