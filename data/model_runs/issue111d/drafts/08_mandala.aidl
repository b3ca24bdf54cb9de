# Mandala wall hanging (home, a gift): a 150 mm disc of 3 mm plywood; 8 petal openings
# (ellipses 36 x 14 mm) radiating from the center, their centers on a 35 mm radius, the first
# pointing right; an 8-point star opening in the middle (tips on 12 mm, notches on 6 mm
# radius); 8 arc slots 5 mm wide on a 62 mm radius, each spanning 30 deg, centered between the
# petals; an engraved circle of 56.5 mm radius between petals and slots; a 4 mm hanging hole at
# the top, its center 69 mm above the disc's center.

thickness 3 mm

solid mandala {
    disc = Circle(center=(0, 0), diameter=150)
    Fixed(disc)

    hole petal {
        e = Ellipse(center=(35, 0), rx=18, ry=7)
    }
    petals = CircularPattern(petal, 8, disc.center)

    hole star {
        s = Star(center=(0, 0), points=8, outer_radius=12, inner_radius=6)
    }

    hole arc {
        a = ArcSlot(center=(0, 0), radius=62, start_angle=7.5 deg, end_angle=37.5 deg, width=5)
    }
    arcs = CircularPattern(arc, 8, disc.center)

    drawing ring {
        c = Circle(center=(0, 0), radius=56.5)
    }

    hole hang {
        c = Circle(center=(0, 69), diameter=4)
    }

    assert disc.diameter == 150 mm, "150 mm disc"
    assert len(petals) == 8, "8 petals"
    assert petal.e.rx == 18 mm and petal.e.ry == 7 mm, "36 x 14 mm petals"
    assert distance(petal.e.center, disc.center) == 35 mm, "petals on a 35 mm radius"
    assert star.s.outer_radius == 12 mm and star.s.inner_radius == 6 mm, "star 12 / 6 mm"
    assert len(arcs) == 8, "8 arc slots"
    assert arc.a.radius == 62 mm and arc.a.width == 5 mm, "5 mm slots on 62 mm"
    assert ring.c.radius == 56.5 mm, "engraved ring"
    assert hang.c.center.y - disc.center.y == 69 mm, "hang hole 69 mm up"
    assert hang.c.diameter == 4 mm, "4 mm hang hole"
}
