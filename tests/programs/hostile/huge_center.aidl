# expect: E0305 3:23
solid s {
    c = Circle(center=(1e9, 0), radius=1)
}
