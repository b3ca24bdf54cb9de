# Request (garden): an escape ramp so hedgehogs and frogs that fall into the pond can climb
# out. 6 mm exterior ply, glued.
# - A ramp board 400 mm long x 120 mm wide, corners R10, laid at 30 degrees from the water up
#   over the pond's edge.
# - Eight cleats across it for grip, 40 mm apart, the first 40 mm from the lower end: each
#   100 mm long, standing 12 mm above the board, held in the board by two 15 mm tabs through
#   mortises (glued).
# - Two 6 mm holes at the top end, 15 mm from it and 90 mm apart, to peg it into the lawn.
# - "HEDGEHOG EXIT" engraved filled across the top end, bold sans, 8 mm letters.

import "std/joints.aidl"

thickness 6 mm
t = 6 mm

param cleats = 8, min = 4, max = 9
pitch = 40 mm
first = 40 mm          # first cleat's centre from the lower end
slope = 30 deg
cleat_len = 100 mm
cleat_h = 12 mm        # above the board

def x_of(i) = first + i * pitch

def cleat() -> solid {
    body = Rectangle(bottom_left=(-cleat_len / 2, -t), width=cleat_len, height=cleat_h + t)
    tabs = tab_and_slot(part="tab", length=cleat_len, thickness=t, tabs=2, tab=15, screw=0,
                        rotation=180 deg, cx=0, cy=-t)
}

assembly wildlife_ramp {
    solid board {
        body = RoundedRectangle(bottom_left=(0, -60), width=400, height=120, corner_radius=10)
        for i in range(cleats) {
            m = tab_and_slot(part="slot", length=cleat_len, thickness=t, tabs=2, tab=15, screw=0,
                             rotation=90 deg, cx=x_of(i), cy=0)
        }
        hole pegs {
            p1 = Circle(center=(385, -45), diameter=6)
            p2 = Circle(center=(385, 45), diameter=6)
        }
        drawing sign {
            word = Text("HEDGEHOG EXIT", position=(360, 0), size=8, font="sans:Bold", fill=true,
                        rotation=90 deg, valign="middle")
        }
    }

    # the board rises along u at 30 deg; its top face looks along n
    u = (cos(slope), 0, sin(slope))
    n = (-sin(slope), 0, cos(slope))
    Place(board, position=(0, 0, 0), face=n, up=(0, 1, 0))

    for i in range(cleats) {
        c = cleat()
        # the cleat's y = 0 on the board's top face, its thickness across the mortise
        Place(c, position=((x_of(i) - t / 2) * cos(slope) - t * sin(slope), 0,
                           (x_of(i) - t / 2) * sin(slope) + t * cos(slope)),
              face=u, up=n)
    }
    # flat on the sheet: the cleats in a row under the board
    Below(c[0], board, gap=5)
    AlignLeft(c[0], board)
    for i in range(1, cleats) {
        RightOf(c[i], c[i - 1], gap=5)
        AlignBottom(c[i], c[0])
    }

    assert len(c) == 8, "eight cleats"
    assert board.body.bb.width == 400 mm and board.body.bb.height == 120 mm, "board 400 x 120"
    assert board.m[1].slot[0].bb.center_x - board.m[0].slot[0].bb.center_x == 40 mm, "cleats 40 apart"
    assert board.m[0].slot[0].bb.center_x - board.body.bb.left == 40 mm, "first cleat 40 up"
    assert c[0].body.bb.height - t == 12 mm, "cleats stand 12 mm"
    assert board.pegs.p2.center.y - board.pegs.p1.center.y == 90 mm, "pegs 90 apart"
    assert board.body.bb.right - board.pegs.p1.center.x == 15 mm, "pegs 15 from the top end"
}
