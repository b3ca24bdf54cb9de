# A flat chess knight, 60 mm tall: a 36 mm wide, 8 mm tall round-cornered
# base, a 26 mm wide collar above it, and the horse's head in profile (facing
# left) with an engraved eye and a mane line.
solid knight {
    base = RoundedRectangle(center=(0, 4), width=36, height=8, corner_radius=2)
    collar = Trapezoid(center=(0, 11), bottom_width=30, top_width=24, height=6)
    head = Polygon([(-12, 14), (12, 14), (13, 30), (10, 44), (3, 54), (-2, 60),
                    (-4, 55), (-10, 52), (-19, 44), (-20, 39), (-15, 37), (-8, 40),
                    (-6, 34), (-12, 24)])
    Fillet(1)
    drawing details {
        eye = Circle(center=(-7, 48), radius=1.2)
        mane = Spline([(1, 54), (8, 44), (10, 30)])
    }
}
