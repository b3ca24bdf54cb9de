# Issue 84: a chess knight aligned on its base, two sibling solids written where they are
# meant to stand: the first-named (the knight) moves onto the second (the base, the
# reference), which stays at (0, 0) (before: both moved halfway, to x = 6).
solid base { b = Rectangle(center=(0, 0), width=40, height=10) }
solid knight { k = Rectangle(center=(12, 20), width=14, height=30) }
AlignCenterX(knight, base)
