# A door hanger with a knob hole and a slit to slide it on.
solid hanger {
    tag = RoundedRectangle(center=(0, 0), width=90, height=230, corner_radius=8)
    hole knob {
        c = Circle(center=(0, 80), diameter=38)
        slit = Rectangle(bottom_left=(-3, 80), width=6, height=40)
    }
    drawing words {
        t = Text("DO NOT DISTURB", position=(0, -20), size=7)
    }
}
