# Raspberry Pi 4 mounting plate: a 105 x 76 mm plate, 3 mm acrylic, 4 mm corner
# radius. The Pi 4 board (85 x 56 mm, engraved outline for alignment) sits
# centered on it; its four M2.5 holes (2.7 mm diameter) form a 58 x 49 mm
# rectangle whose bottom-left hole is 3.5 mm in from the board's left and bottom
# edges. Four 4.2 mm holes (M4) 6 mm in from each plate corner fix the plate.
# Five 4 x 30 mm vertical vent slots, 8 mm apart, under the middle of the board.

units mm
thickness 3 mm

solid plate {
    body = RoundedRectangle(center=(0, 0), width=105, height=76, corner_radius=4)

    drawing board {
        outline = Rectangle(center=(0, 0), width=85, height=56)
        pattern = Rectangle(center=(0, 0), width=58, height=49, construction=true)
        At(pattern.bottom_left, outline.bottom_left, dx=3.5, dy=3.5)
    }
    CenterInside(board.outline, body)

    hole pi {
        c = Circle(center=(0, 0), diameter=2.7)
    }
    pi_holes = CornerPattern(pi, board.pattern)

    hole mount {
        c = Circle(center=(0, 0), diameter=4.2)
    }
    mounts = CornerPattern(mount, body, inset=6)

    hole vent {
        s = Slot(center=(0, 0), length=30, width=4, rotation=90)
    }
    vents = LinearPattern(vent, 5, (8, 0))
    vents[2].s.center.x == board.outline.center.x
    vents[2].s.center.y == board.outline.center.y
}
