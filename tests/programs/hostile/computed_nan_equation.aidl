# expect: E0112 4:17
solid s {
    c = Circle((0, 0), 5)
    c.radius == 1e200 * 1e200 - 1e200 * 1e200
}
