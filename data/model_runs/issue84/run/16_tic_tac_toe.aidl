# A tic-tac-toe set: a 120 x 120 mm board with the 3 x 3 grid engraved (cells
# 34 mm), and five X pieces and five O pieces, each 28 mm across, cut as
# separate pieces beside the board.
param cell = 34 mm

def x_piece() -> solid {
    a = Rectangle(center=(0, 0), width=28, height=7, rotation=45 deg)
    b = Rectangle(center=(0, 0), width=28, height=7, rotation=-45 deg)
}

def o_piece() -> solid {
    ring = Circle(center=(0, 0), diameter=28)
    hole inside { c = Circle(center=(0, 0), diameter=16) }
}

assembly set {
    solid board {
        plate = RoundedRectangle(center=(0, 0), width=120, height=120, corner_radius=6)
        drawing grid {
            v1 = Line((-cell / 2, -1.5 * cell), (-cell / 2, 1.5 * cell))
            v2 = Line((cell / 2, -1.5 * cell), (cell / 2, 1.5 * cell))
            h1 = Line((-1.5 * cell, -cell / 2), (1.5 * cell, -cell / 2))
            h2 = Line((-1.5 * cell, cell / 2), (1.5 * cell, cell / 2))
        }
    }
    for i in range(5) {
        x = x_piece()
        x.bb.center == (82, -64 + i * 32)
        o = o_piece()
        o.bb.center == (118, -64 + i * 32)
    }
}
