# Clock face: a 220 mm square face with 20 mm corner radii, a 7.5 mm shaft hole
# in the middle, twelve engraved hour marks (12 mm long lines, 90 mm from the
# centre to their outer end) and the numerals 12, 3, 6 and 9 engraved 18 mm high.

solid face {
    board = RoundedRectangle(center=(0, 0), width=220, height=220, corner_radius=20)
    hole shaft { c = Circle(center=(0, 0), diameter=7.5) }
    drawing marks {
        for i in range(12) {
            m = Line(polar((0, 0), 78, i * 30 deg), polar((0, 0), 90, i * 30 deg))
        }
    }
    drawing numerals {
        n12 = Text("12", (0, 62), size=18, valign="middle")
        n3 = Text("3", (62, 0), size=18, valign="middle")
        n6 = Text("6", (0, -62), size=18, valign="middle")
        n9 = Text("9", (-62, 0), size=18, valign="middle")
    }
}
