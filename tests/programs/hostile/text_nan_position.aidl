# expect: E0112 5:32
solid s {
    c = Circle((0, 0), 5)
    big = 1e14 * 1e14 * 1e14 * 1e14 * 1e14 * 1e14 * 1e14 * 1e14 * 1e14 * 1e14 * 1e14 * 1e14
    drawing d { t = Text("x", (big * big * big - big * big * big, 0)) }
}
