# Chess knight silhouette (about 40 x 60 mm) for a laser-cut chess set,
# with an engraved eye and an engraved mouth line. Facing left.

param base_w = 40 mm
param base_h = 8 mm

solid knight {
    # the base: a flat foot the piece stands on
    base = RoundedRectangle(center=(0, 4), width=base_w, height=base_h, corner_radius=2)
    Fixed(base)

    # the head and neck profile, facing left (literal coordinates: rigid)
    head = Polygon([
        (-14, 7),    # front of the neck at the base
        (-10, 22),
        (-12, 28),   # throat
        (-19, 33),   # under the jaw
        (-20, 38),   # mouth corner / muzzle bottom
        (-17, 44),   # nose top
        (-8, 52),    # forehead
        (-4, 56),    # ear front
        (0, 60),     # ear tip
        (3, 54),     # ear back
        (10, 50),    # mane top
        (15, 40),
        (16, 26),
        (14, 7)      # back of the neck at the base
    ])
    Above(head, base, gap=-1)

    drawing face {
        eye = Circle(center=(-7, 45), radius=1.8)
        mouth = Line(start=(-19.5, 38), end=(-13, 37))
    }
    Rigid(face, head)
}
