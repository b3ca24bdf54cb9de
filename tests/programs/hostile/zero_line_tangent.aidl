# expect: E0108 5:5
solid s {
    l = Line((0, 0), (0, 0))
    c = Circle((5, 0), 2)
    Tangent(l, c)
}
