# Travel tic-tac-toe set, 3 mm plywood. Board: 120 x 120 mm, R8 corners, a centered 3 x 3
# grid of 34 mm squares engraved as its four inner lines (two across, two up, each 102 mm
# long). Ten loose pieces, separate parts: five X's, each two 28 mm long, 7 mm wide
# round-ended bars crossing at their middles at +45 and -45 deg; five O's, each a 28 mm ring
# with a 14 mm hole. Laid out for cutting below the board: the X's in a row 4 mm under it,
# the O's in a row 4 mm under the X's, pieces 32 mm apart center to center, each row
# centered under the board.
units mm
thickness 3 mm

param cell = 34 mm, min = 30 mm, max = 36 mm

def xpiece() -> solid {
    a = Slot(center=(0, 0), length=28, width=7, rotation=45 deg)
    b = Slot(center=(0, 0), length=28, width=7, rotation=-45 deg)
}

def opiece() -> solid {
    ring = Circle(center=(0, 0), diameter=28)
    hole eye {
        c = Circle(center=(0, 0), diameter=14)
    }
}

assembly game {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=120, height=120, corner_radius=8)
        drawing grid {
            for k in range(2) {
                v = Line(((k - 0.5) * cell, -1.5 * cell), ((k - 0.5) * cell, 1.5 * cell))
                h = Line((-1.5 * cell, (k - 0.5) * cell), (1.5 * cell, (k - 0.5) * cell))
            }
        }
        CenterInside(grid, body)
    }

    for i in range(5) {
        x = xpiece()
        x.a.center.x == board.body.center.x + (i - 2) * 32 mm
        x.bb.top == board.body.bb.bottom - 4 mm
    }
    for i in range(5) {
        o = opiece()
        o.ring.center.x == board.body.center.x + (i - 2) * 32 mm
        o.bb.top == x[0].bb.bottom - 4 mm
    }

    assert board.body.bb.width == 120 mm and board.body.bb.height == 120 mm, "board 120 x 120 mm"
    assert board.grid.v[1].start.x - board.grid.v[0].start.x == 34 mm, "34 mm squares"
    assert board.grid.v[0].length == 102 mm and board.grid.h[0].length == 102 mm, "lines 102 mm"
    assert board.grid.bb.center_x == board.body.center.x and board.grid.bb.center_y == board.body.center.y, "grid centered"
    assert len(x) == 5 and len(o) == 5, "five X's and five O's"
    assert x[0].a.length == 28 mm and x[0].a.width == 7 mm, "X bars 28 x 7 mm"
    assert o[0].ring.diameter == 28 mm and o[0].eye.c.diameter == 14 mm, "O ring 28 / 14 mm"
    assert board.body.bb.bottom - x[0].bb.top == 4 mm, "X row 4 mm under the board"
    assert x[0].bb.bottom - o[0].bb.top == 4 mm, "O row 4 mm under the X's"
    assert x[1].a.center.x - x[0].a.center.x == 32 mm, "pieces 32 mm apart"
}
