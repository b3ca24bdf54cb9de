# 30 x 80 mm hinge leaf, three 4 mm holes 25 mm apart on the centreline.
solid leaf {
    body = Rectangle(center=(0, 0), width=30, height=80)
    hole h { c = Circle(center=(0, -25), diameter=4) }
    LinearPattern(h, 3, (0, 25))
}
