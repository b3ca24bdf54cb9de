# A 150 mm ruler: 160 x 30 mm plate, 1 mm ticks engraved from the bottom edge
# starting 5 mm in from the left end (1 mm: 4 mm long, 5 mm: 6 mm long, 10 mm:
# 9 mm long), the numbers 0-15 engraved 3 mm high above the centimetre ticks,
# and a 5 mm hanging hole at the right end.
solid ruler {
    body = RoundedRectangle(bottom_left=(0, 0), width=160, height=30, corner_radius=2)
    hole hang { c = Circle(center=(154, 22), diameter=5) }
    drawing scale {
        for i in range(151) {
            t = Line((5 + i, 0), (5 + i, 9 if i % 10 == 0 else (6 if i % 5 == 0 else 4)))
        }
        for k in range(16) {
            n = Text(str(k), (5 + k * 10, 11), size=3)
        }
    }
}
