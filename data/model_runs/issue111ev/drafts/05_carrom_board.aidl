# Request: a tabletop travel carrom board, cut from 6 mm birch ply (fits my 600 x 400 bed).
# - Board 390 x 390 mm; a frame of four 40 mm rails glued on top leaves a 310 x 310 playing
#   area. The top and bottom rails run the full 390; the left and right rails fit between
#   them and lock in with one flat sliding dovetail at each end (12 mm deep, 10 degrees,
#   0.1 mm clearance), so the frame is cut from strips.
# - Four 20 mm pockets, centres 11 mm in from both rail edges at each corner of the play area.
# - Engraved markings: on each side two baselines 13 mm apart, the outer one 42 mm in from the
#   rail, 200 mm long overall, closed at each end by a 13 mm circle with a filled 10 mm disc.
#   A centre circle 13 mm and an outer circle 70 mm, an 8-point star (R30 / R12) between them.
#   Four arrows on the diagonals from 21 mm to 133 mm from each pocket centre, a filled
#   arrowhead (8 mm long, 6 mm wide) at the pocket end, a half-circle R13 about the inner end
#   on the centre side.

import "std/joints.aidl"

thickness 6 mm

board_w = 390 mm
rail = 40 mm
play = board_w - 2 * rail          # 310
half = play / 2                    # 155
dt_depth = 12 mm
pocket_in = 11 mm
pc = half - pocket_in              # pocket centre, each axis
base_out = 42 mm
base_gap = 13 mm
base_len = 200 mm
d = 1 / sqrt(2)

def short_rail(x=0 mm) -> solid {
    body = Rectangle(center=(x, 0), width=rail, height=play + 2 * dt_depth)
    top = dovetail(part="tail", length=rail, depth=dt_depth, tails=1, angle=10 deg,
                   cx=x, cy=half)
    bottom = dovetail(part="tail", length=rail, depth=dt_depth, tails=1, angle=10 deg,
                      rotation=180 deg, cx=x, cy=-half)
}

def long_rail(y=0 mm, r=0 deg) -> solid {
    body = Rectangle(center=(0, y), width=board_w, height=rail)
    left = dovetail(part="socket", length=rail, depth=dt_depth, tails=1, angle=10 deg,
                    clearance=0.1 mm, rotation=r, cx=-half - rail / 2,
                    cy=y - rail / 2 if r == 0 deg else y + rail / 2)
    right = dovetail(part="socket", length=rail, depth=dt_depth, tails=1, angle=10 deg,
                     clearance=0.1 mm, rotation=r, cx=half + rail / 2,
                     cy=y - rail / 2 if r == 0 deg else y + rail / 2)
}

assembly carrom {
    solid board {
        body = Rectangle(center=(0, 0), width=board_w, height=board_w)
        hole pocket {
            c = Circle(center=(-pc, -pc), diameter=20)
        }
        pockets = CornerPattern(pocket, at=[(-pc, -pc), (pc, -pc), (pc, pc), (-pc, pc)])

        drawing baseline {
            outer = Line((-base_len / 2 + base_gap / 2, -half + base_out),
                         (base_len / 2 - base_gap / 2, -half + base_out))
            inner = Line((-base_len / 2 + base_gap / 2, -half + base_out + base_gap),
                         (base_len / 2 - base_gap / 2, -half + base_out + base_gap))
            e1 = Circle(center=(-base_len / 2 + base_gap / 2, -half + base_out + base_gap / 2),
                        diameter=base_gap)
            e2 = Circle(center=(base_len / 2 - base_gap / 2, -half + base_out + base_gap / 2),
                        diameter=base_gap)
            f1 = Circle(center=(-base_len / 2 + base_gap / 2, -half + base_out + base_gap / 2),
                        diameter=10, fill=true)
            f2 = Circle(center=(base_len / 2 - base_gap / 2, -half + base_out + base_gap / 2),
                        diameter=10, fill=true)
        }
        baselines = CircularPattern(baseline, 4, (0, 0))

        drawing arrow {
            shaft = Line((-pc + 21 * d, -pc + 21 * d), (-pc + 133 * d, -pc + 133 * d))
            head = Polygon([(-pc + 21 * d, -pc + 21 * d),
                            (-pc + 29 * d + 3 * d, -pc + 29 * d - 3 * d),
                            (-pc + 29 * d - 3 * d, -pc + 29 * d + 3 * d)], fill=true)
            curl = Arc(center=(-pc + 133 * d, -pc + 133 * d), radius=13, start_angle=-45 deg,
                       end_angle=135 deg)
        }
        arrows = CircularPattern(arrow, 4, (0, 0))

        drawing centre {
            small = Circle(center=(0, 0), diameter=13)
            big = Circle(center=(0, 0), diameter=70)
            star = Star(center=(0, 0), points=8, outer_radius=30, inner_radius=12)
        }
        Fixed(body)
    }

    left = short_rail(x=-half - rail / 2)
    right = short_rail(x=half + rail / 2)
    top = long_rail(y=half + rail / 2, r=0 deg)
    bottom = long_rail(y=-half - rail / 2, r=180 deg)

    # on the sheet: rails beside and under the board
    RightOf(left, board, gap=6)
    AlignTop(left, board)
    RightOf(right, left, gap=6)
    AlignTop(right, left)
    Below(top, board, gap=6)
    AlignLeft(top, board)
    Below(bottom, top, gap=6)
    AlignLeft(bottom, top)

    # 3D: rails glued on the board as drawn in their frames
    Place(board, position=(0, 0, 0), face="up")
    Place(left, position=(0, 0, 6 mm), face="up")
    Place(right, position=(0, 0, 6 mm), face="up")
    Place(top, position=(0, 0, 6 mm), face="up")
    Place(bottom, position=(0, 0, 6 mm), face="up")

    assert board.body.bb.width == 390 mm and board.body.bb.height == 390 mm, "board 390 square"
    assert top.body.bb.width == 390 mm and top.body.bb.height == 40 mm, "long rails 390 x 40"
    assert left.body.bb.width == 40 mm, "short rails 40 wide"
    assert board_w - 2 * rail == 310 mm, "310 play area"
    assert len(board.pockets) == 4, "four pockets"
    assert board.pocket.c.diameter == 20 mm, "20 mm pockets"
    assert board.pocket.c.center.x - (board.body.bb.left + 40 mm) == 11 mm, "pocket 11 in from the rail"
    assert board.baseline.outer.start.y - (board.body.bb.bottom + 40 mm) == 42 mm, "baseline 42 in"
    assert board.baseline.inner.start.y - board.baseline.outer.start.y == 13 mm, "baselines 13 apart"
    assert board.baseline.e2.right.x - board.baseline.e1.left.x == 200 mm, "baseline 200 long"
    assert board.centre.big.diameter == 70 mm and board.centre.small.diameter == 13 mm, "centre circles"
    assert abs(distance(board.arrow.shaft.start, board.pocket.c.center) - 21 mm) < 0.01 mm, "arrow starts 21 from the pocket"
    assert abs(distance(board.arrow.shaft.end, board.pocket.c.center) - 133 mm) < 0.01 mm, "arrow ends 133 from the pocket"
    assert distance(board.arrow, board.baseline) >= 1 mm, "arrows clear of the baselines"
    assert distance(board.arrow, board.pocket) >= 1 mm, "arrows clear of the pocket"
}
