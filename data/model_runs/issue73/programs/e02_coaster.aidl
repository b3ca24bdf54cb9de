# A round coaster with a ring of small holes around a centre hole.
param d = 95 mm
solid coaster {
    disc = Circle(center=(0, 0), diameter=d)
    hole centre { c = Circle(center=(0, 0), diameter=12) }
    hole ring { c = Circle(center=(0, 28), diameter=8) }
    CircularPattern(ring, 12, disc.center)
    Distance(ring.c.center, disc.center, 28)
    hole outer { c = Circle(center=(0, 40), diameter=4) }
    CircularPattern(outer, 24, disc.center)
}
