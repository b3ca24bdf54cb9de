# expect: E0108 3:9
solid s {
    p = Polygon([(0, 0), (10, 0), (10, 0), (0, 10)])
}
