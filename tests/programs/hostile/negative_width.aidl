# expect: E0108 3:9
solid s {
    r = Rectangle(center=(0, 0), width=-3, height=2)
}
