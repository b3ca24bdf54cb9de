# Gifts: a child's name puzzle "MIA", 6 mm plywood, 5 parts. A top board 200 x 90 mm (R8 corners)
# with the letters M, I, A cut out as openings: sans Bold, 50 mm cap height, their centres 55 mm
# apart on the board's middle line, each opening 0.2 mm larger all round than its letter
# (clearance). The three letters cut as separate pieces. A plain backing board 200 x 90 mm (R8)
# is glued under the top board (it also holds the island inside the A's opening).
thickness 6 mm

letters = ["M", "I", "A"]
cap = 50 mm
pitch = 55 mm
clearance = 0.2 mm

assembly puzzle {
    solid board {
        plate = RoundedRectangle(center=(0, 0), width=200, height=90, corner_radius=8)
        hole openings {
            for i in range(3) {
                o = Offset(Text(letters[i], position=((i - 1) * pitch, 0), size=cap,
                                font="sans:Bold", valign="middle"), clearance)
            }
        }
    }
    for i in range(3) {
        solid piece {
            t = Text(letters[i], position=((i - 1) * pitch, -90), size=cap, font="sans:Bold",
                     valign="middle")
        }
    }
    solid back {
        plate = RoundedRectangle(center=(0, -190), width=200, height=90, corner_radius=8)
    }

    assert board.plate.bb.width == 200 mm and board.plate.bb.height == 90 mm, "board 200 x 90"
    assert back.plate.bb.width == 200 mm and back.plate.bb.height == 90 mm, "back 200 x 90"
    assert len(piece) == 3, "3 letters"
    assert piece[0].t.size == 50 mm, "50 mm letters"
    assert piece[1].t.position.x - piece[0].t.position.x == 55 mm, "55 apart"
    assert board.openings.o[0].bb.width - piece[0].t.bb.width == 0.4 mm, "0.2 clearance each side (M)"
    assert board.openings.o[2].bb.height - piece[2].t.bb.height == 0.4 mm, "0.2 clearance each side (A)"
}
