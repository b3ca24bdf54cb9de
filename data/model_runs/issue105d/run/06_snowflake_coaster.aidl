# Round coaster: 100 mm diameter disc; an engraved six-fold snowflake centred on it,
# each arm 36 mm long with two pairs of side branches (at 14 mm: 9 mm long, at
# 24 mm: 6 mm long, 45 deg off the arm); an engraved ring 4 mm inside the rim.
param d = 100 mm, min = 80 mm, max = 120 mm
param arm = 36 mm, min = 20 mm, max = 42 mm
thickness 3 mm

solid coaster {
    disc = Circle(center=(0, 0), diameter=d)
    drawing flake_arm {
        spine = Line((0, 0), (0, arm))
        b1l = Line((0, 14), (-9 * cos(45 deg), 14 + 9 * sin(45 deg)))
        b1r = Line((0, 14), (9 * cos(45 deg), 14 + 9 * sin(45 deg)))
        b2l = Line((0, 24), (-6 * cos(45 deg), 24 + 6 * sin(45 deg)))
        b2r = Line((0, 24), (6 * cos(45 deg), 24 + 6 * sin(45 deg)))
    }
    Rigid(flake_arm)
    Coincident(flake_arm.spine.start, disc.center)
    arms = CircularPattern(flake_arm, 6, disc.center)
    drawing rim {
        ring = Circle(center=(0, 0), radius=d / 2 - 4)
    }
    Concentric(rim.ring, disc)
    assert len(arms) == 6, "six-fold"
    assert flake_arm.spine.length == 36 mm, "arm 36 mm"
}
