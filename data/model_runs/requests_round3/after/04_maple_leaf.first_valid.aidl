# A maple-leaf coaster about 90 mm across, symmetric about its vertical axis,
# with a 3 mm hanging hole near the top.
thickness 3 mm

solid coaster {
    # right half of the leaf outline (x >= 0), mirrored about the y axis
    leaf = Polygon([
        (0, 45), (6, 30), (14, 36), (12, 18), (28, 26), (24, 18), (45, 16),
        (36, 6), (42, 0), (28, -8), (32, -18), (16, -14), (6, -22), (3, -24),
        (3, -40), (0, -40)
    ], mirror="y")
    hole hang { c = Circle(center=(0, 36), diameter=3) }
}
