# Tic-tac-toe: a 150 mm square board (5 mm corner radius) with an engraved 3 x 3
# grid of 45 mm cells and an engraved outline 6 mm in; five X pieces and four O
# pieces, 34 mm across, cut beside the board (O: ring with a 16 mm hole; X: two
# 8 mm bars crossed at 45 degrees).

param cell = 45 mm

def ex(x=0 mm, y=0 mm) -> solid {
    a = Rectangle(center=(x, y), width=34, height=8, rotation=45 deg)
    b = Rectangle(center=(x, y), width=34, height=8, rotation=-45 deg)
}

def oh(x=0 mm, y=0 mm) -> solid {
    ring = Circle(center=(x, y), diameter=34)
    hole mid { c = Circle(center=(x, y), diameter=16) }
}

assembly game {
    solid board {
        b = RoundedRectangle(center=(0, 0), width=150, height=150, corner_radius=5)
        drawing grid {
            v1 = Line((-cell / 2, -1.5 * cell), (-cell / 2, 1.5 * cell))
            v2 = Line((cell / 2, -1.5 * cell), (cell / 2, 1.5 * cell))
            h1 = Line((-1.5 * cell, -cell / 2), (1.5 * cell, -cell / 2))
            h2 = Line((-1.5 * cell, cell / 2), (1.5 * cell, cell / 2))
            frame = Rectangle(center=(0, 0), width=138, height=138)
        }
    }
    for i in range(5) {
        xp = ex(x=100 + 40 * (i % 3), y=50 - 40 * (i // 3))
    }
    for i in range(4) {
        op = oh(x=100 + 40 * (i % 3), y=-40 - 40 * (i // 3))
    }
}
