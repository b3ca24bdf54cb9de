# expect: E0108 5:5
solid s {
    a = Line((0, 0), (0, 0))
    b = Line((0, 0), (10, 0))
    Angle(a, b, 30 deg)
}
