# Chess knight silhouette (about 40 x 60 mm) for a laser-cut chess set,
# with an engraved eye and an engraved mouth line. The knight faces left.

solid knight {
    base = RoundedRectangle(bottom_left=(-20, 0), width=40, height=8, corner_radius=2)
    collar = Trapezoid(center=(0, 10), bottom_width=34, top_width=28, height=4)
    head = Polygon([(-14, 11), (14, 11), (15, 22), (14, 34), (11, 44), (6, 52),
                    (2, 57), (-1, 60), (-4, 54), (-10, 50), (-16, 42), (-19, 36),
                    (-19, 32), (-15, 29), (-9, 30), (-6, 26), (-10, 18)])
    Fixed(base)
    Above(collar, base, gap=-0.5)
    AlignCenterX(collar, base)
    Above(head, collar, gap=-1)

    drawing face {
        eye = Circle(center=(-6, 45), radius=1.8)
        mouth = Line((-18, 33.5), (-12, 32.5))
    }
    Rigid(head, face)
}
