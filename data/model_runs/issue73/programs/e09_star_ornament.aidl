# A star ornament with a hanging hole.
solid ornament {
    star = Star(center=(0, 0), points=6, outer_radius=40, inner_radius=20)
    hole hang { c = Circle(center=(0, 32), diameter=4) }
}
