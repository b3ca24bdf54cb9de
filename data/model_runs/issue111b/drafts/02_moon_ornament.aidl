# Crescent moon ornament, 3 mm birch: the moon is an 80 mm disc with a 64 mm disc cut away,
# the cut disc's center 22 mm right of the moon's center (horns point right).
# A 4 mm hanging hole on the moon's vertical center line, its center 6 mm below the top;
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
        c = Circle(center=(0, moon_d / 2 - 6 mm), diameter=4)
    }

    drawing deco {
        s = Star(center=(-25, 0), points=5, outer_radius=6, inner_radius=2.5)
    }

    assert disc.diameter == 80 mm, "moon 80 mm"
    assert bite.c.diameter == 64 mm, "bite 64 mm"
    assert abs(bite.c.center.x - disc.center.x - 22 mm) < 0.001 mm, "bite 22 mm right of center"
    assert abs(disc.bb.top - hang.c.center.y - 6 mm) < 0.001 mm, "hole 6 mm below the top"
    assert abs(disc.center.x - deco.s.center.x - 25 mm) < 0.001 mm, "star 25 mm left of center"
}
