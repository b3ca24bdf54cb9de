# expect: E0304 3:9
solid s {
    t = f"{1:999999999}"
    c = Circle((0, 0), 1)
}
