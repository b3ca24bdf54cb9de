# expect: E0112 3:9
solid s {
    i = 1 / 5e-324
    c = Circle(center=(0, 0), radius=i - i)
}
