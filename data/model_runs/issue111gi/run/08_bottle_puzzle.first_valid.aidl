# Request: a wine-bottle puzzle as a birthday gift: the bottle is locked in it until the puzzle
# is solved. 6 mm ply. An oval board 220 x 70 mm with a 33 mm hole in the middle (slides over
# a wine bottle's neck and its 31 mm lip) and a 10 mm rope hole 90 mm either side of the middle;
# "HAPPY 40TH" engraved left of the neck hole and "SOLVE ME" right of it (7 mm letters, kept
# 5 mm clear of the holes). Two toggles for the rope's ends, each three 24 mm discs glued up
# with a 5 mm hole for the rope (a knot inside), too big to pass the 10 mm rope holes.

thickness 6 mm

def toggle_disc() -> solid {
    c = Circle(center=(0, 0), diameter=24)
    hole rope { h = Circle(center=(0, 0), diameter=5) }
}

assembly bottle_puzzle {
    solid board {
        body = Ellipse(center=(0, 0), rx=110, ry=35)
        hole neck { c = Circle(center=(0, 0), diameter=33) }
        hole rope_l { c = Circle(center=(-90, 0), diameter=10) }
        hole rope_r { c = Circle(center=(90, 0), diameter=10) }
        drawing words {
            left = Text("HAPPY 40TH", position=(-50, 0), size=7, valign="middle",
                        max_width=52 mm)
            right = Text("SOLVE ME", position=(50, 0), size=7, valign="middle",
                         max_width=52 mm)
        }
        Fixed(body)
    }

    for j in range(6) {
        disc = toggle_disc()
        disc.bb.center == (-75 + 30 * j, -60)
    }

    # in 3D: the board flat, the toggles stacked three and three under the rope holes
    Place(board, position=(0, 0, 0), face="up")
    for j in range(3) {
        Place(disc[j], position=(-90, 0, -40 + 6 * j), face="up")
        Place(disc[j + 3], position=(90, 0, -40 + 6 * j), face="up")
    }

    assert board.body.bb.width == 220 mm and board.body.bb.height == 70 mm, "board 220 x 70"
    assert board.neck.c.diameter == 33 mm and board.neck.c.diameter > 31 mm, "over the lip"
    assert board.rope_r.c.center.x - board.neck.c.center.x == 90 mm, "rope holes 90 out"
    assert disc[0].c.diameter > board.rope_l.c.diameter, "toggle can't pass"
    assert len(disc) == 6, "two toggles of three"
    assert distance(board.words.left, board.neck) >= 5 mm, "words clear of the neck hole"
    assert distance(board.words.left, board.rope_l) >= 5 mm, "words clear of the rope hole"
    assert distance(board.words.right, board.neck) >= 5 mm, "words clear of the neck hole"
    assert distance(board.words.right, board.rope_r) >= 5 mm, "words clear of the rope hole"
}
