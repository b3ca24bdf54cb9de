# Lamp shade top ring, 3 mm plywood: a flat ring 180 mm outer diameter with a
# 120 mm round opening, and 8 holes 6 mm in diameter evenly spaced on a 150 mm
# diameter circle (concentric), the first one straight up at 12 o'clock, for
# lacing the shade's fabric panels.

units mm
thickness 3 mm

param holes = 8, min = 3, max = 16
param pcd = 150 mm, min = 130 mm, max = 170 mm

solid ring {
    outer = Circle(center=(0, 0), diameter=180)
    hole opening {
        c = Circle(center=(0, 0), diameter=120)
    }
    Concentric(opening.c, outer)

    hole lace {
        c = Circle(center=(0, 75), diameter=6)
    }
    Coincident(lace.c.center, polar(outer.center, pcd / 2, 90 deg))
    laces = CircularPattern(lace, holes, outer.center)
}
