# Request (parties): a free-standing donut wall for a birthday table, 6 mm ply.
# - board 400 mm wide, 520 mm tall at its straight sides, an arched top rising to 600 mm
#   at the centre (one arc through both top corners);
# - 20 peg holes for 12 mm dowels (12.2 mm holes) in 5 rows of 4, 90 mm apart in a row,
#   rows 85 mm apart, every second row shifted half a step (brick pattern), the pattern
#   centred left-right, the lowest row 90 mm above the bottom edge;
# - "DONUTS" engraved as filled bold letters 50 mm tall, centred left-right, their middle
#   530 mm above the bottom edge; "HELP YOURSELF" engraved single-line 14 mm tall,
#   centred, baseline 20 mm above the bottom edge;
# - two feet 160 x 50 mm, cross-halved with the board 120 mm either side of its centre:
#   25 mm notches up from the board's bottom edge and down from each foot's top centre;
# - joints 0.2 mm loose.

import "std/joints.aidl"

units mm
thickness 6 mm

T = 6 mm
fit = 0.2 mm
board_w = 400 mm
side_h = 520 mm
arch_h = 600 mm
peg_d = 12.2 mm
rows = 5
cols = 4
peg_dx = 90 mm
peg_dy = 85 mm
foot_x = 120 mm
foot_len = 160 mm
foot_h = 50 mm
halving = 25 mm

assembly donut_wall {
    solid board {
        bottom = Line((-board_w / 2, 0), (board_w / 2, 0))
        right = Line((board_w / 2, 0), (board_w / 2, side_h))
        top = Arc(start=(board_w / 2, side_h), through=(0, arch_h), end=(-board_w / 2, side_h))
        left = Line((-board_w / 2, side_h), (-board_w / 2, 0))
        Fixed(bottom)
        Fixed(right)
        Fixed(top)
        Fixed(left)

        hole peg {
            c = Circle(center=(-(cols - 1) * peg_dx / 2 - peg_dx / 4, 90), diameter=peg_d)
        }
        pegs = GridPattern(peg, rows, cols, (peg_dx, peg_dy), stagger=true)

        notch_l = cross_halving(depth=halving, thickness=T, clearance=fit, rotation=180 deg,
                                cx=-foot_x, cy=0)
        notch_r = cross_halving(depth=halving, thickness=T, clearance=fit, rotation=180 deg,
                                cx=foot_x, cy=0)

        drawing title {
            t = Text("DONUTS", position=(0, 530), size=50, font="sans:Bold", valign="middle",
                     fill=true)
        }
        drawing footer {
            t = Text("HELP YOURSELF", position=(0, 20), size=14)
        }
    }

    solid foot_l {
        body = Rectangle(center=(0, 0), width=foot_len, height=foot_h)
        Fixed(body)
        slot = cross_halving(depth=halving, thickness=T, clearance=fit, cx=0, cy=foot_h / 2)
    }
    solid foot_r {
        body = Rectangle(center=(0, 0), width=foot_len, height=foot_h)
        Fixed(body)
        slot = cross_halving(depth=halving, thickness=T, clearance=fit, cx=0, cy=foot_h / 2)
    }

    Fixed(board)
    RightOf(foot_l, board, gap=10)
    AlignBottom(foot_l, board)
    Above(foot_r, foot_l, gap=10)
    AlignLeft(foot_r, foot_l)

    assert board.bb.width == 400 mm, "board 400 wide"
    assert abs(board.bb.height - 600 mm) < 0.01 mm, "arch 600 tall at the centre"
    assert board.right.length == 520 mm, "sides 520 tall"
    assert len(board.pegs) == 20, "20 pegs"
    assert abs(board.pegs[0].c.center.y - board.bottom.start.y - 90 mm) < 0.01 mm, "lowest row 90 up"
    assert abs(board.pegs[1].c.center.x - board.pegs[0].c.center.x - 90 mm) < 0.01 mm, "90 apart"
    assert abs(board.pegs[4].c.center.y - board.pegs[0].c.center.y - 85 mm) < 0.01 mm, "rows 85 apart"
    assert abs((board.pegs[0].c.center.x + board.pegs[7].c.center.x) / 2) < 0.01 mm, "pegs centred"
    assert board.title.bb.top < board.top.through.y, "title under the arch"
    assert board.title.bb.bottom > board.pegs[19].c.center.y + 40 mm, "a donut on the top row clears the title"
    assert foot_l.body.bb.width == 160 mm and foot_l.body.bb.height == 50 mm, "feet 160 x 50"
    assert halving + halving == foot_h, "halvings add up to the foot's height"
}
