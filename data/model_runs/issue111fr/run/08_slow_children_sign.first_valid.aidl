# Request: a "SLOW - children at play" sign for the edge of a shared driveway.
# - Board: 6 mm exterior ply 360 x 240, R15 corners, an engraved border line 10 mm in (R8).
#   "SLOW" cut right through as stencil letters (bold sans, 55 mm tall, at most 200 wide),
#   centred 55 mm right of the board's centre and 20 mm above it. "CHILDREN AT PLAY"
#   fill-engraved in bold sans 22 mm tall (at most 320 wide), centred, its middle 75 below
#   the centre.
# - A running child with a ball, cut from 3 mm yellow acrylic and glued on the left half of
#   the board: head R14 centred at (-115, 75), body, arms and legs as 10-12 mm bands, the
#   ball R11 at the kicking foot; all one piece, at least 8 mm clear of the text and the
#   screw holes.
# - Two stakes in 6 mm ply, 50 wide x 500 long, the last 60 tapering to a point, screwed
#   behind the board (their tops 20 below its top, their middles 150 either side of the
#   centre) with two M4 countersunk screws each: board holes 4.5 mm, 9 mm countersinks, at
#   (+-150, +-90); 3 mm pilot holes in the stakes to match.

thickness 6 mm

BW = 360 mm
BH = 240 mm
SX = 150 mm
HOLES = [(-SX, 90 mm), (SX, 90 mm), (-SX, -90 mm), (SX, -90 mm)]
STAKE_TOP = BH / 2 - 20 mm

def stake() -> solid {
    post = Polygon([(-25, 0), (25, 0), (25, -440), (0, -500), (-25, -440)])
    hole pilots {
        a = Circle(center=(0, 90 - STAKE_TOP), diameter=3)
        b = Circle(center=(0, -90 - STAKE_TOP), diameter=3)
    }
}

assembly sign {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=BW, height=BH, corner_radius=15)
        hole slow {
            t = Text("SLOW", position=(55, 20), size=55, font="sans:Bold", valign="middle",
                     stencil=true, max_width=200)
        }
        hole screws {
            for p in HOLES {
                c = Circle(center=p, diameter=4.5)
            }
        }
        Countersink(screws, diameter=9)
        drawing border {
            line = RoundedRectangle(center=(0, 0), width=BW - 20 mm, height=BH - 20 mm,
                                    corner_radius=8)
        }
        drawing words {
            t = Text("CHILDREN AT PLAY", position=(0, -75), size=22, font="sans:Bold",
                     valign="middle", fill=true, max_width=320)
        }
    }

    solid child {
        thickness 3 mm
        head = Circle(center=(-115, 75), radius=14)
        body = Stroke(Line((-115, 64), (-108, 12)), width=12)
        arm_back = Stroke(Polyline([(-113, 50), (-135, 38), (-148, 50)]), width=10)
        arm_front = Stroke(Polyline([(-113, 50), (-92, 40), (-84, 55)]), width=10)
        leg_back = Stroke(Polyline([(-108, 12), (-128, -12), (-146, -34)]), width=10)
        leg_front = Stroke(Polyline([(-108, 12), (-92, -12), (-78, -30)]), width=10)
        ball = Circle(center=(-66, -36), radius=11)
    }

    left_stake = stake()
    right_stake = stake()

    # flat: the child right of the board, the stakes below
    RightOf(child, board, gap=10)
    AlignTop(child, board)
    Below(left_stake, board, gap=10)
    AlignLeft(left_stake, board)
    RightOf(right_stake, left_stake, gap=10)
    AlignTop(right_stake, left_stake)

    # assembled: the board upright reading from the front; the child on its face; the
    # stakes behind it
    Place(board, position=(0, 0, 0), face="front", up="up")
    Place(child, on=board, position=(0, 0))
    Place(left_stake, position=(-SX, 6, STAKE_TOP), face="front", up="up")
    Place(right_stake, position=(SX, 6, STAKE_TOP), face="front", up="up")

    assert board.body.bb.width == 360 mm and board.body.bb.height == 240 mm, "360 x 240"
    assert board.slow.bb.width <= 200 mm, "SLOW at most 200 wide"
    assert board.slow.t.position.x - board.body.bb.center_x == 55 mm, "SLOW 55 right"
    assert board.words.t.position.y - board.body.bb.center_y == -75 mm, "words 75 below"
    assert len(board.screws.c) == 4 and board.screws.c[0].diameter == 4.5 mm, "4 x 4.5 mm"
    assert board.body.bb.right - board.border.line.bb.right == 10 mm, "border 10 in"
    assert distance(board.slow, board.screws) >= 8 mm, "SLOW clear of the screws"
    assert distance(board.words, board.screws) >= 8 mm, "words clear of the screws"
    assert distance(child, board.words) >= 8 mm, "child clear of the words"
    assert distance(child, board.slow) >= 8 mm, "child clear of SLOW"
    assert distance(child, board.screws) >= 8 mm, "child clear of the screws"
    assert child.head.radius == 14 mm and child.ball.radius == 11 mm, "head R14, ball R11"
    assert left_stake.post.bb.width == 50 mm and left_stake.post.bb.height == 500 mm,
        "stakes 50 x 500"
    assert left_stake.pilots.a.center.y - left_stake.pilots.b.center.y == 180 mm,
        "pilots match the board's holes"
}
