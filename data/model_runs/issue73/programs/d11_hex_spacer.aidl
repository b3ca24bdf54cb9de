# 40 mm across-flats hexagon spacer with an 8 mm bore.
solid spacer {
    hex = RegularPolygon(center=(0, 0), across_flats=40, sides=6)
    hole bore { c = Circle(center=(0, 0), diameter=8) }
}
