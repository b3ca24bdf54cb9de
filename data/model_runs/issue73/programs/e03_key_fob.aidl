# A key fob with my initials engraved and a hole for the key ring.
solid fob {
    body = RoundedRectangle(center=(0, 0), width=50, height=25, corner_radius=6)
    hole ring { c = Circle(center=(-18, 0), diameter=5) }
    drawing initials {
        t = Text("JK", position=(5, 0), size=12, valign="middle")
    }
}
