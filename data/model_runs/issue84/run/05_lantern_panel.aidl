# A lantern side panel: 100 x 150 mm, a 10 mm solid border, a 3 x 4 grid of
# star cut-outs (5 points, 9 mm outer radius) at 26 mm pitch centred in the
# panel, and a 6 mm hanging hole centred 6 mm below the top edge.
solid panel {
    body = Rectangle(center=(0, 0), width=100, height=150)
    hole star {
        s = Star(center=(-26, -39), points=5, outer_radius=9, inner_radius=4)
    }
    GridPattern(star, rows=4, cols=3, spacing=(26, 26))
    hole hang { c = Circle(center=(0, 69), diameter=6) }
}
