# Crescent moon ornament, 3 mm birch: the moon is an 80 mm disc with a 64 mm disc cut away,
# the cut disc's center 22 mm right of the moon's center (horns point right).
# A 4 mm hanging hole above the crescent's centroid (15 mm left of the moon's center, so it
# hangs level), its center 6 mm in from the moon's edge;
# an engraved five-point star (outer radius 6 mm, inner 2.5 mm) in the crescent's widest part,
# its center 25 mm left of the moon's center.

units mm
thickness 3 mm

param moon_d = 80 mm, min = 50 mm, max = 150 mm
param bite_d = 64 mm, min = 30 mm, max = 120 mm
param bite_offset = 22 mm, min = 10 mm, max = 40 mm

solid moon {
    disc = Circle(center=(0, 0), diameter=moon_d)

    hole bite {
        c = Circle(center=(bite_offset, 0), diameter=bite_d)
    }

    hole hang {
        # the crescent's centroid lies ~15 mm left of the disc's center (hung at x = 0 it tilts 24 deg)
        c = Circle(center=(-15, sqrt((moon_d / 2 - 6 mm) ** 2 - (15 mm) ** 2)), diameter=4)
    }

    drawing deco {
        s = Star(center=(-25, 0), points=5, outer_radius=6, inner_radius=2.5)
    }

    assert disc.diameter == 80 mm, "moon 80 mm"
    assert bite.c.diameter == 64 mm, "bite 64 mm"
    assert abs(bite.c.center.x - disc.center.x - 22 mm) < 0.001 mm, "bite 22 mm right of center"
    assert abs(distance(hang.c.center, disc.center) - (moon_d / 2 - 6 mm)) < 0.001 mm, "hole 6 mm in from the edge"
    assert abs(disc.center.x - deco.s.center.x - 25 mm) < 0.001 mm, "star 25 mm left of center"
}
