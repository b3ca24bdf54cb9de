# Snowflake ornament: six arms 5 mm wide with round tips, 85 mm across the arm
# tips (each arm 40 mm from the center to its tip's arc center); each arm has
# two 4 mm wide branches 12 mm long, leaving the arm 22 mm from the center at
# 60 degrees to it; a 16 mm hexagon (across flats) at the center with a 6 mm
# hexagonal hole; an 8 mm ring centered on the top arm's tip with a 3 mm
# hanging hole in it.

param arm_len = 40 mm, min = 30 mm, max = 60 mm

solid snowflake {
    core = RegularPolygon(center=(0, 0), across_flats=16, sides=6)
    hole eye_hex { h = RegularPolygon(center=(0, 0), across_flats=6, sides=6) }
    Concentric(eye_hex.h, core)

    solid arm {
        bar = Slot(start=(0, 0), length=arm_len + 5 mm, angle=90 deg, width=5)  # length is tip to tip
        left = Slot(start=(0, 22), length=12, angle=150 deg, width=4)
        right = Slot(start=(0, 22), length=12, angle=30 deg, width=4)
        At(left.start, bar.start, dy=22)
        At(right.start, bar.start, dy=22)
    }
    Coincident(arm.bar.start, core.center)
    arms = CircularPattern(arm, 6, core.center)

    ring = Circle(center=(0, 40), diameter=8)
    Coincident(ring.center, arm.bar.end)
    hole hang { c = Circle(center=(0, 40), diameter=3) }
    Concentric(hang.c, ring)

    assert len(arms) == 6, "six arms"
    assert arm.bar.end.y - core.center.y == 40 mm, "arm length"
}
