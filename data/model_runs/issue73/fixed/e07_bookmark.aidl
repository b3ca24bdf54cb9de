# A bookmark with a heart cut-out and a tassel hole.
solid bookmark {
    body = RoundedRectangle(center=(0, 0), width=40, height=150, corner_radius=5)
    hole heart {
        l = Circle(center=(-4, 52), radius=5)
        r = Circle(center=(4, 52), radius=5)
        tip = Polygon([(-8.5, 49.5), (8.5, 49.5), (0, 40)])
    AllowOverlap(l, r)
    }
    hole tassel { c = Circle(center=(0, 66), diameter=5) }
}
