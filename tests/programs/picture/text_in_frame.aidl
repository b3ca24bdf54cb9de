# A door sign: the name in a frame whose edge runs 0.24 mm from the letters
# (issue 84: "make the text smaller", followed, still warned).
solid sign {
    body = RoundedRectangle(center=(0, 0), width=80, height=30, corner_radius=4)
    drawing face {
        frame = Rectangle(center=(0, 0), width=50, height=6.48)
        name = Text("KITCHEN", (0, 0), size=6, valign="middle")
    }
}
