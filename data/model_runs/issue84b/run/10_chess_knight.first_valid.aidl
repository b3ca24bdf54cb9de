# Chess knight for a flat (3 mm) chess set: 70 mm tall overall, standing on a
# 40 x 8 mm base with a 30 x 5 mm collar above it; a horse head profile facing
# left, an engraved eye and an engraved nostril, an engraved mane line.

solid knight {
    base = RoundedRectangle(center=(0, 4), width=40, height=8, corner_radius=2)
    collar = Rectangle(center=(0, 10.5), width=30, height=5)
    head = Polygon([(-12, 12), (12, 12), (14, 30), (12, 48), (6, 62), (0, 70),
                    (-4, 66), (-10, 60), (-20, 50), (-22, 44), (-18, 40),
                    (-8, 44), (-10, 30)])
    drawing face {
        eye = Circle(center=(-6, 56), radius=1.5)
        nostril = Circle(center=(-18, 45), radius=1)
        mane = Spline([(4, 66), (10, 52), (11, 36), (8, 20)])
    }
}
