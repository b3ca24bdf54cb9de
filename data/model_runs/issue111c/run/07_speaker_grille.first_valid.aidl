# Speaker grille for a 4 in driver: a 120 mm disc with a field of 5 mm holes on
# a hexagonal grid (7 mm pitch) filling a 90 mm circle in the middle, and four
# 4 mm mounting holes on a 106 mm bolt circle at 45, 135, 225 and 315 deg.
thickness 3 mm

param pitch = 7 mm, min = 6 mm, max = 12 mm
field_r = 45 mm
n = 7

solid grille {
    disc = Circle(center=(0, 0), diameter=120)
    hole vents {
        for r in range(-n, n + 1) {
            for k in range(-n, n + 1) {
                if sqrt(square(k * pitch + (r % 2) * pitch / 2) + square(r * pitch * sqrt(3) / 2)) <= field_r - 2.5 mm {
                    v = Circle(center=(k * pitch + (r % 2) * pitch / 2, r * pitch * sqrt(3) / 2), diameter=5)
                }
            }
        }
    }
    hole mount {
        c = Circle(center=(53 * cos(45 deg), 53 * sin(45 deg)), diameter=4)
    }
    mounts = CircularPattern(mount, 4, disc.center)
    Fixed(mount)
}

assert grille.disc.diameter == 120 mm, "120 mm disc"
assert grille.vents.bb.width <= 90 mm and grille.vents.bb.height <= 90 mm, "vents within 90 mm"
assert len(grille.mounts) == 4, "four mounting holes"
assert abs(distance(grille.mount.c.center, grille.disc.center) - 53 mm) < 0.001 mm, "106 mm bolt circle"
assert grille.mount.c.diameter == 4 mm, "4 mm"
