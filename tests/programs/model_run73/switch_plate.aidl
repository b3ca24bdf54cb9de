# Issue 73 model run, d10: two screw holes 60.3 mm apart, tied to each other only.
solid plate {
    body = RoundedRectangle(center=(0, 0), width=70, height=115, corner_radius=3)
    hole opening { r = Rectangle(center=(0, 0), width=10.3, height=23.8) }
    CenterInside(opening, body)
    hole top_screw { c = Circle(center=(0, 30.15), diameter=3.5) }
    hole bottom_screw { c = Circle(center=(0, -30.15), diameter=3.5) }
    VerticalDistance(bottom_screw.c.center, top_screw.c.center, 60.3)
}
