// Issue 84: a plate whose corner hole is placed three times over. W0401 offered to keep the
// HorizontalDistance and drop the VerticalDistance and the CornerPattern: done as told, the
// plate had 2 openings instead of 5 and the hole slid in y (W0404). The CornerPattern makes
// the copies and places the hole in x and y: it stays, the two distances go.
solid plate {
    body = Rectangle(center=(0, 0), width=80, height=50)
    hole corner { c = Circle(center=(-34, -19), diameter=4) }
    hole window { r = Rectangle(center=(0, 0), width=20, height=10) }
    HorizontalDistance(body.left.midpoint, corner.c.center, 6 mm)
    VerticalDistance(body.bottom.midpoint, corner.c.center, 6 mm)
    CornerPattern(corner, body, inset=6 mm)
}
