# Request (parties): a balloon sizer for building balloon garlands, in inches as balloons are
# sold, cut from 6 mm ply on a 900 x 600 mm laser. A board 28 x 14 in (corners r 0.5 in) with
# three round holes 5, 9 and 11 in across in a row, 0.75 in of wood between them and at the
# ends, their bottoms all 1.25 in above the bottom edge. Above each hole its size engraved
# ("5 IN", "9 IN", "11 IN", bold filled, 0.6 in tall) centred 0.8 in below the top edge, and
# "BALLOON SIZER" (0.45 in) over the 9 in hole, 2.3 in below the top. A 4 x 1.25 in hand slot
# over the 5 in hole, centred 9.5 in up. The board stands on two feet 9 x 2.5 in (top corners
# r 0.5 in) crossing it 1.25 in in from each end, cross-halved (0.2 mm clearance).

units in
thickness 6 mm

import "std/joints.aidl"

W = 28
HT = 14
WEB = 0.75
LIFT = 1.25           # the holes' bottoms above the bottom edge
SIZES = [5, 9, 11]
FOOT_L = 9
FOOT_H = 2.5
FOOT_IN = 1.25        # the feet's middles in from the board's ends
T = 6 mm

def hole_x(i) = WEB * (i + 1) + sum([SIZES[k] for k in range(i)]) + SIZES[i] / 2

def foot() -> solid {
    body = RoundedRectangle(bottom_left=(0, 0), width=FOOT_L, height=FOOT_H,
                            corner_radii=[0.5, 0.5, 0, 0])
    notch = cross_halving(depth=FOOT_H / 2, thickness=T, clearance=0.2 mm,
                          cx=FOOT_L / 2, cy=FOOT_H)
}

assembly sizer {
    solid board {
        body = RoundedRectangle(bottom_left=(0, 0), width=W, height=HT, corner_radius=0.5)
        for i in range(3) {
            hole gauge { c = Circle(center=(hole_x(i), LIFT + SIZES[i] / 2), diameter=SIZES[i]) }
        }
        hole hand { s = Slot(center=(hole_x(0), 9.5), length=4, width=1.25) }
        left_notch = cross_halving(depth=FOOT_H / 2, thickness=T, clearance=0.2 mm,
                                   rotation=180 deg, cx=FOOT_IN, cy=0)
        right_notch = cross_halving(depth=FOOT_H / 2, thickness=T, clearance=0.2 mm,
                                    rotation=180 deg, cx=W - FOOT_IN, cy=0)
        drawing labels {
            for i in range(3) {
                size = Text(f"{SIZES[i]} IN", position=(hole_x(i), HT - 0.8), size=0.6,
                            font="sans:Bold", valign="middle", fill=true)
            }
            title = Text("BALLOON SIZER", position=(hole_x(1), HT - 2.3), size=0.45,
                         font="sans:Bold", valign="middle", fill=true)
        }
    }
    foot_l = foot()
    foot_r = foot()

    # on the sheet: the feet under the board
    Below(foot_l, board, gap=0.3)
    Below(foot_r, board, gap=0.3)
    AlignLeft(foot_l, board)
    AlignRight(foot_r, board)

    # assembled: the board upright across x, the feet along y through its notches
    Place(board, position=(-W / 2, T / 2, 0), rotation=(90 deg, 0, 0))
    Place(foot_l, position=(-W / 2 + FOOT_IN - T / 2, -FOOT_L / 2, 0), rotation=(90 deg, 0, 90 deg))
    Place(foot_r, position=(W / 2 - FOOT_IN - T / 2, -FOOT_L / 2, 0), rotation=(90 deg, 0, 90 deg))

    # the request's numbers
    assert board.gauge[0].c.diameter == 5 in and board.gauge[1].c.diameter == 9 in and
        board.gauge[2].c.diameter == 11 in, "5, 9, 11 in"
    assert board.gauge[0].c.center.x - board.gauge[0].c.radius - board.body.bb.left == 0.75 in, "end web"
    assert board.body.bb.right - (board.gauge[2].c.center.x + board.gauge[2].c.radius) == 0.75 in, "other end web"
    assert (board.gauge[1].c.center.x - board.gauge[1].c.radius) - (board.gauge[0].c.center.x + board.gauge[0].c.radius) == 0.75 in, "web 1"
    assert (board.gauge[2].c.center.x - board.gauge[2].c.radius) - (board.gauge[1].c.center.x + board.gauge[1].c.radius) == 0.75 in, "web 2"
    assert board.body.bb.width == 28 in and board.body.bb.height == 14 in, "28 x 14 in"
    assert board.gauge[2].c.center.y - board.gauge[2].c.radius - board.body.bb.bottom == 1.25 in, "holes 1.25 up"
    assert board.left_notch.cut.bb.top - board.body.bb.bottom == 1.25 in, "board notch half the foot"
    # bed 900 x 600 mm
    assert board.body.bb.width <= 900 mm and board.body.bb.height <= 600 mm, "fits the bed"
}
