# Hexagonal coaster: a regular hexagon 100 mm across flats (flats at top and
# bottom) with its six corners rounded to 5 mm, and an engraved double ring
# centered on it: circles of 80 mm and 74 mm diameter.

param af = 100 mm, min = 80 mm, max = 120 mm

solid coaster {
    body = RegularPolygon(center=(0, 0), across_flats=af, sides=6)
    Fillet(5)
    drawing ring {
        outer = Circle(center=(0, 0), diameter=0.8 * af)
        inner = Circle(center=(0, 0), diameter=0.8 * af - 6 mm)
        Concentric(inner, outer)
    }
    Concentric(ring.outer, body)

    assert body.bb.height == af, "100 mm across flats"
    assert ring.outer.diameter == 80 mm and ring.inner.diameter == 74 mm, "ring sizes"
}
