# Switch plate 70 x 115 mm, opening 23.8 x 10.3 mm, two 3.5 mm screw holes 60.3 mm apart.
solid plate {
    body = RoundedRectangle(center=(0, 0), width=70, height=115, corner_radius=3)
    hole opening { r = Rectangle(center=(0, 0), width=10.3, height=23.8) }
    hole top_screw { c = Circle(center=(0, 30.15), diameter=3.5) }
    hole bottom_screw { c = Circle(center=(0, -30.15), diameter=3.5) }
    VerticalDistance(bottom_screw.c.center, top_screw.c.center, 60.3)
    top_screw.bb.center == (0, 30.15)
    AlignCenterX(bottom_screw, body)
}
