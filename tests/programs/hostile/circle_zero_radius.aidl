# expect: E0108 3:9
solid s {
    c = Circle(center=(0, 0), radius=0)
}
