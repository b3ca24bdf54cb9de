# expect: E0305 3:40
solid s {
    r = Rectangle(center=(0, 0), width=1e11, height=1)
}
