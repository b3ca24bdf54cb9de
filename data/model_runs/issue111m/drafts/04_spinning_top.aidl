# Toy spinning top disc, 4 mm acrylic: a 70 mm disc with a 6 mm hole in its centre for
# the dowel spindle; six 12 mm round windows evenly round a 44 mm circle (centres 22 mm
# from the middle), the first on +x; a five-pointed star engraved round the spindle
# (tips 12 mm, notches 6 mm from the centre, first tip up); an engraved ring of 31 mm
# radius near the rim.

thickness 4 mm

param windows = 6, min = 3, max = 8

solid top {
    disc = Circle(center=(0, 0), diameter=70)

    hole spindle {
        c = Circle(center=(0, 0), diameter=6)
    }
    Concentric(spindle.c, disc)

    hole window {
        c = Circle(center=(22, 0), diameter=12)
    }
    ring = CircularPattern(window, windows, disc.center)

    drawing deco {
        star = Star(center=(0, 0), points=5, outer_radius=12, inner_radius=6)
        rim = Circle(center=(0, 0), radius=31)
    }
    Concentric(deco.star, disc)

    assert disc.diameter == 70 mm, "70 mm disc"
    assert spindle.c.diameter == 6 mm, "6 mm spindle hole"
    assert distance(spindle.c.center, disc.center) == 0 mm, "spindle centred"
    assert len(ring) == 6, "six windows"
    assert window.c.diameter == 12 mm, "12 mm windows"
    assert distance(ring[3].c.center, disc.center) == 22 mm, "windows 22 from the middle"
    assert window.c.center.y == disc.center.y and window.c.center.x > disc.center.x, "first window on +x"
    assert deco.star.outer_radius == 12 mm and deco.star.inner_radius == 6 mm, "star 12 / 6"
    assert deco.rim.radius == 31 mm, "ring at 31"
}
