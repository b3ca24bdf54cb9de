# Honeycomb trivet: a hexagon 160 mm across flats with a 5 x 5 staggered field of
# hexagonal openings 20 mm across flats, 24 mm apart, centred; a 10 mm rim at least.
param cell = 20 mm, min = 14 mm, max = 24 mm
pitch = 24 mm
solid trivet {
    body = RegularPolygon(center=(0, 0), across_flats=160, sides=6, rotation=30)
    hole cells {
        for r in range(5) {
            for c in range(5 - abs(r - 2)) {
                h = RegularPolygon(center=((c - (4 - abs(r - 2)) / 2) * pitch, (r - 2) * pitch * sqrt(3) / 2), across_flats=cell, sides=6, rotation=30)
            }
        }
    }
    CenterInside(cells, body)
}
