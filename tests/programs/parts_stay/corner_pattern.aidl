# Issue 73: a plate written at (0, 0) and a hole at (0, 0) placed by CornerPattern with an
# inset: the plate stays where it is written, the holes go to its corners (before: the
# plate moved to (33.649, 13.057) and the hole stayed at (0, 0)).
solid plate {
    body = Rectangle(center=(0, 0), width=120, height=70)
    hole h { c = Circle(center=(0, 0), diameter=5) }
    CornerPattern(h, body, inset=(26.3507, 21.9429))
}
