# 90 x 90 plate, 2.75 mm holes on a 58 x 49 mm rectangle, 10 mm from the bottom-left.
solid mount {
    body = Rectangle(bottom_left=(0, 0), width=90, height=90)
    pattern = Rectangle(bottom_left=(10, 10), width=58, height=49, construction=true)
    hole m { c = Circle(center=(10, 10), diameter=2.75) }
    CornerPattern(m, pattern)
}
