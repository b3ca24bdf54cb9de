# A maple-leaf coaster about 90 mm across, symmetric about its vertical axis,
# with a 3 mm hanging hole near the top.

param hang_d = 3 mm

solid leaf {
    # the right half, from the top tip clockwise to the foot of the stem, closed along x = 0
    half = Polygon([(0, 45), (5, 33), (10, 36), (10, 22), (16, 25), (9, 10), (22, 20),
                    (25, 27), (31, 21), (45, 25), (37, 12), (42, 5), (24, 2), (30, -12),
                    (20, -11), (16, -17), (3, -10), (1.5, -12), (1.5, -28), (0, -28)])
    axis = Line((0, -30), (0, 50), construction=true)
    Fixed(axis)     # the line of symmetry x = 0
    Fixed(half)
    other = Mirrored(half, about=axis)

    hole hang {
        c = Circle(center=(0, 30), diameter=hang_d)
    }
    Fixed(hang)
}
