# Bracket: 80 x 30 mm flange with a 30 deg bend relief notch, two 5 mm holes 15 mm from the ends.
solid bracket {
    flange = Rectangle(bottom_left=(0, 0), width=80, height=30)
    hole relief { v = Triangle(center=(40, 27), base=2 * 3 * tan(15 deg), height=6, rotation=180) }
    AlignTop(relief, flange)
    AlignCenterX(relief, flange)
    hole left { c = Circle(center=(15, 15), diameter=5) }
    hole right { c = Circle(center=(65, 15), diameter=5) }
}
