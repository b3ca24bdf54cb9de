# Request (toys): a pentomino puzzle in 3 mm ply for a 9-year-old: the 12 pentominoes (F I L N P
# T U V W X Y Z) made of 20 mm squares, each with its letter engraved 8 mm tall in its most
# central square; a tray that holds them as a 6 x 10 rectangle (120 x 200 mm, +0.5 mm all round
# for play): a frame with a 12 mm border and 6 mm corner radii, glued on a base of the same
# outline; the frame has a 16 mm round thumb notch at the middle of each short end of the
# opening to lift pieces out, and "PENTOMINO" engraved 6 mm tall centred in its top border.
# Pieces are cut from one 120 x 200 block laid out as a solution, which is also how they go in
# the tray.

thickness 3 mm

U = 20 mm          # square
PLAY = 0.5 mm      # all round the 6 x 10 opening
BORDER = 12 mm
OPEN_W = 10 * U + 2 * PLAY
OPEN_H = 6 * U + 2 * PLAY
OUT_W = OPEN_W + 2 * BORDER
OUT_H = OPEN_H + 2 * BORDER

# one solution of the 6 x 10 rectangle; each piece's first square is its most central one
PIECES = [
    ["F", [[1, 1], [0, 1], [0, 0], [1, 2], [2, 1]]],
    ["I", [[2, 0], [3, 0], [4, 0], [1, 0], [5, 0]]],
    ["L", [[4, 1], [5, 1], [6, 1], [3, 1], [6, 0]]],
    ["N", [[2, 2], [2, 3], [3, 2], [1, 3], [4, 2]]],
    ["P", [[8, 5], [8, 4], [9, 4], [9, 5], [7, 5]]],
    ["T", [[4, 5], [4, 4], [3, 5], [4, 3], [5, 5]]],
    ["U", [[5, 2], [6, 2], [7, 2], [5, 3], [7, 3]]],
    ["V", [[8, 0], [9, 0], [9, 1], [7, 0], [9, 2]]],
    ["W", [[2, 4], [2, 5], [3, 4], [1, 5], [3, 3]]],
    ["X", [[6, 4], [5, 4], [6, 3], [6, 5], [7, 4]]],
    ["Y", [[0, 4], [0, 3], [0, 2], [0, 5], [1, 4]]],
    ["Z", [[8, 1], [8, 2], [8, 3], [7, 1], [9, 3]]],
]

def piece(letter="F", cells=[]) -> solid {
    for c in cells {
        sq = Rectangle(bottom_left=(c[0] * U, c[1] * U), width=U, height=U)
    }
    drawing mark {
        t = Text(letter, position=((cells[0][0] + 0.5) * U, (cells[0][1] + 0.5) * U), size=8 mm,
                 valign="middle")
    }
}

# the tray's frame and base are drawn above the pieces' block on the sheet
TRAY_X = 5 * U
FRAME_Y = 6 * U + 10 mm + OUT_H / 2
BASE_Y = FRAME_Y + OUT_H + 10 mm

assembly pentomino_puzzle {
    for p in PIECES {
        pc = piece(letter=p[0], cells=p[1])
    }

    solid frame {
        body = RoundedRectangle(center=(TRAY_X, FRAME_Y), width=OUT_W, height=OUT_H,
                                corner_radius=6 mm)
        hole opening {
            r = Rectangle(center=(TRAY_X, FRAME_Y), width=OPEN_W, height=OPEN_H)
            notch_l = Circle(center=(TRAY_X - OPEN_W / 2, FRAME_Y), diameter=16 mm)
            notch_r = Circle(center=(TRAY_X + OPEN_W / 2, FRAME_Y), diameter=16 mm)
        }
        drawing title {
            t = Text("PENTOMINO", position=(TRAY_X, FRAME_Y + OPEN_H / 2 + BORDER / 2), size=6 mm,
                     valign="middle")
        }
    }

    solid base {
        body = RoundedRectangle(center=(TRAY_X, BASE_Y), width=OUT_W, height=OUT_H,
                                corner_radius=6 mm)
    }

    # in 3D: the base on the table, the frame on it, the pieces in the opening as cut
    Place(base, position=(0, 6 * U / 2 - BASE_Y, 0), face="up")
    Place(frame, position=(0, 6 * U / 2 - FRAME_Y, 3 mm), face="up")
    for i in range(12) {
        Place(pc[i], position=(0, 0, 3 mm), face="up")
    }

    assert len(pc) == 12, "twelve pentominoes"
    assert sum([len(p[1]) for p in PIECES]) == 60, "5 squares each"
    assert frame.opening.r.bb.width == 200 mm + 1 mm and frame.opening.r.bb.height == 120 mm + 1 mm,
        "6 x 10 squares of 20 mm, 0.5 mm play all round"
    assert frame.body.bb.width - frame.opening.r.bb.width == 2 * 12 mm, "12 mm border"
    assert frame.opening.notch_l.diameter == 16 mm, "16 mm thumb notch"
    assert pc[0].mark.t.size == 8 mm, "letters 8 mm"
}
