# NEMA 17 mount: 60 x 60 mm, 22 mm central bore, four M3 holes on a 31 mm square.
thickness 3 mm
solid mount {
    body = RoundedRectangle(center=(30, 30), width=60, height=60, corner_radius=4)
    hole bore { c = Circle(center=(0, 0), diameter=22) }
    Concentric(bore.c, body)
    square = Rectangle(center=(0, 0), width=31, height=31, construction=true)
    Concentric(square, body)
    hole m3 { c = Circle(center=(0, 0), diameter=3.4) }
    CornerPattern(m3, square)
}
