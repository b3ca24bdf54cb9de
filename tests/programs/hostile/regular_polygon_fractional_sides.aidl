# expect: E0108 3:9
solid s {
    p = RegularPolygon(center=(0, 0), radius=5, sides=3.5)
}
