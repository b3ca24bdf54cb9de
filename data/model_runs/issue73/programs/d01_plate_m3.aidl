# 60 x 40 mm plate, 3 mm thick, four M3 holes 5 mm in from each corner, 20 mm central bore.
thickness 3 mm
solid plate {
    body = Rectangle(center=(0, 0), width=60, height=40)
    hole m3 { c = Circle(center=(0, 0), diameter=3.2) }
    CornerPattern(m3, body, inset=5)
    hole bore { c = Circle(center=(0, 0), diameter=20) }
    Concentric(bore.c, body)
}
