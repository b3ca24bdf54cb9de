# Request: a fire plank (Finnish loimulohi board) for cooking a salmon side by the camp
# fire, cut from 9 mm birch ply. The board is 200 x 400 mm, top corners R20, with a 25 mm
# hanging hole centred 30 mm below the top. The fish is pinned with T-shaped pegs through
# eight rectangular holes, 8.3 x 9.3 mm (for an 8 mm shank of 9 mm ply, the 9 mm upright),
# in two columns 70 mm either side of the centre line and four rows 80 mm apart, the lowest
# 70 mm above the bottom edge. Ten pegs (two spare): a 30 x 10 mm head and an 8 mm shank
# 45 mm long with a 2 mm chamfer at the tip. A detachable ground stake, 60 mm wide and
# 250 mm long overall with a 55 mm point, slides onto the board's bottom edge with a
# two-tail sliding dovetail 15 mm deep (sockets 0.2 mm looser). Engraved: "LOIMULOHI" (filled
# serif bold, 12 mm) between the top pegs and the hanging hole, "THIS SIDE TO THE FIRE"
# (6 mm strokes) 30 mm above the bottom edge.

import "std/joints.aidl"

t = 9 mm
thickness t

peg_xs = [-70, 70]
peg_ys = [70, 150, 230, 310]

def fire_board() -> solid {
    body = RoundedRectangle(center=(0, 200), width=200, height=400, corner_radii=[20, 20, 0, 0])
    hole hang { c = Circle(center=(0, 370), diameter=25) }
    for y in peg_ys {
        for x in peg_xs {
            hole peg_hole { r = Rectangle(center=(x, y), width=8.3, height=9.3) }
        }
    }
    socket = dovetail(part="socket", length=60 mm, depth=15 mm, tails=2, angle=10 deg,
                      clearance=0.2 mm, cx=0 mm, cy=0 mm)
    drawing marks {
        name = Text("LOIMULOHI", position=(0, 340), size=12, font="serif:Bold",
                    valign="middle", fill=true)
        side = Text("THIS SIDE TO THE FIRE", position=(0, 30), size=6, valign="middle")
    }
}

def ground_stake() -> solid {
    body = Polygon([(-30, 15), (30, 15), (30, -180), (0, -235), (-30, -180)])
    tails = dovetail(part="tail", length=60 mm, depth=15 mm, tails=2, angle=10 deg,
                     cx=0 mm, cy=0 mm)
}

def fish_peg() -> solid {
    shape = Polygon([(0, 10), (15, 10), (15, 0), (4, 0), (4, -43), (2, -45), (0, -45)],
                    mirror="y")
}

assembly fire_plank {
    board = fire_board()
    stake = ground_stake()
    RightOf(stake, board, gap=10)
    AlignTop(stake, board)
    for i in range(10) {
        peg = fish_peg()
        peg.bb.center == (170 mm + (i % 5) * 36 mm, (i // 5) * -62 mm + 360 mm)
    }

    # 3D: standing upright facing the fire (front), the stake's point 235 mm into the ground
    Place(board, position=(0, 0, 235), face="front", up="up")
    Place(stake, position=(0, 0, 235), face="front", up="up")
    # the eight working pegs through their holes, heads 30 mm (the fish) in front of the board
    for i in range(8) {
        Place(peg[i], position=(peg_xs[i % 2] * 1 mm, -39 mm, 235 mm + peg_ys[i // 2] * 1 mm + 4.5 mm),
              face="down", up="front")
    }

    # the request's numbers
    assert abs(board.body.width - 200 mm) < 0.01 mm and abs(board.body.height - 400 mm) < 0.01 mm, "board 200 x 400"
    assert abs(board.body.bb.top - board.hang.c.center.y - 30 mm) < 0.01 mm, "hanging hole 30 mm below the top"
    assert abs(board.hang.c.diameter - 25 mm) < 0.01 mm, "25 mm hanging hole"
    assert len(board.peg_hole) == 4 and len(board.peg_hole[0]) == 2, "eight peg holes"
    assert abs(board.peg_hole[0][1].r.center.x - board.peg_hole[0][0].r.center.x - 140 mm) < 0.01 mm, "columns 70 mm either side"
    assert abs(board.peg_hole[1][0].r.center.y - board.peg_hole[0][0].r.center.y - 80 mm) < 0.01 mm, "rows 80 mm apart"
    assert abs(board.peg_hole[0][0].r.center.y - board.body.bb.bottom - 70 mm) < 0.01 mm, "lowest row 70 mm up"
    assert abs(board.peg_hole[0][0].r.width - 8.3 mm) < 0.01 mm and abs(board.peg_hole[0][0].r.height - 9.3 mm) < 0.01 mm, "8.3 x 9.3 holes"
    assert len(peg) == 10, "ten pegs"
    assert abs(peg[0].shape.bb.width - 30 mm) < 0.01 mm and abs(peg[0].shape.bb.height - 55 mm) < 0.01 mm, "30 mm head, 45 mm shank"
    assert abs(stake.body.bb.height - 250 mm) < 0.01 mm and abs(stake.body.bb.width - 60 mm) < 0.01 mm, "stake 60 x 250"
    assert distance(board.marks.name, board.hang) >= 5 mm, "name clear of the hanging hole"
    assert distance(board.marks.side, board.socket) >= 5 mm, "bottom line clear of the dovetail"
}
