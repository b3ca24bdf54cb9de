# Seed-tray label: a stake 120 mm long x 20 mm wide, its bottom end pointed (a 25 mm
# long point), top corners rounded 3 mm, engraved "BASIL" 8 mm tall on the upper part.
solid label {
    stem = RoundedRectangle(bottom_left=(0, 25), width=20, height=95, corner_radii=[3, 3, 0, 0])
    point = Triangle(center=(10, 12.5), base=20, height=25, rotation=180)
    Below(point, stem)
    AlignCenterX(point, stem)
    drawing word {
        t = Text("BASIL", position=(10, 80), size=8, valign="middle", rotation=90)
    }
    AlignCenterX(word, stem)
    word.bb.center_y == stem.bb.top - 35
}
