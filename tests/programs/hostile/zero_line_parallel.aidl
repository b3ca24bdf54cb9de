# expect: E0108 5:5
solid s {
    a = Line((3, 3), (3, 3))
    b = Line((0, 0), (10, 0))
    Parallel(a, b)
}
