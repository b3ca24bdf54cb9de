# 100 x 50 mm plate, 2 mm corner radii, 40 x 20 mm rectangular cut-out centred.
solid plate {
    body = RoundedRectangle(center=(50, 25), width=100, height=50, corner_radius=2)
    hole window { w = Rectangle(center=(0, 0), width=40, height=20) }
    CenterInside(window, body)
}
