# Request: a wall rack for my hole-saw kit, cut from 6 mm birch ply. Eight saws (19, 25, 32,
# 38, 44, 51, 57 and 64 mm) stay on their arbours and hang by the arbours' 3/8-inch hex shanks
# in U-slots 12 mm wide, open at the front of a shelf 80 mm deep. Each slot's round end (the
# shank's centre) is 45 mm from the back board's front face, so the 64 mm saw clears the board.
# Neighbouring saws are 6 mm apart, and the outer saws 20 mm in from the shelf's ends. The
# shelf is glued into the back board on two 20 mm tabs; the back board is as wide as the
# shelf and 140 mm tall, the shelf's top 30 mm below the board's top. Two right-angled
# brackets, 70 x 70, sit under the shelf 8 mm in from its ends (their middles), each with one
# 30 mm tab into the board and one into the shelf. The board hangs on four 4.5 mm screws
# countersunk for 9 mm heads: two 12 mm below the top edge and two 15 mm above the bottom,
# 40 mm in from the sides. "HOLE SAWS" is engraved on the board above the shelf, and each
# saw's size is engraved on the shelf behind its slot.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
saws = [19, 25, 32, 38, 44, 51, 57, 64]
gap = 6 mm
margin = 20 mm
W = sum(saws) + gap * (len(saws) - 1) + 2 * margin
shelf_depth = 80 mm
board_h = 140 mm
shelf_top = board_h - 30 mm
reach = 45 mm
br = 70 mm
br_in = 8 mm

# centre of saw i along the shelf (x = 0 is the middle)
def saw_x(i) = -W / 2 + margin + sum([saws[j] for j in range(i)]) + saws[i] / 2 + gap * i

def bracket() -> solid {
    body = Polygon([(0, 0), (br, 0), (0, -br)])
    # top edge: a tab up into the shelf; back edge: a tab into the board
    top = tab_and_slot(part="tab", length=br, thickness=t, tabs=1, tab=30 mm, screw=0,
                       cx=br / 2, cy=0 mm)
    back = tab_and_slot(part="tab", length=br, thickness=t, tabs=1, tab=30 mm, screw=0,
                        rotation=90 deg, cx=0 mm, cy=-br / 2)
}

assembly rack {
    solid board {
        body = Rectangle(bottom_left=(-W / 2, 0), width=W, height=board_h)
        shelf_mortise = tab_and_slot(part="slot", length=W, thickness=t, tabs=2, tab=20 mm,
                                     screw=0, cx=0 mm, cy=shelf_top - t / 2)
        for s in [-1, 1] {
            br_mortise = tab_and_slot(part="slot", length=br, thickness=t, tabs=1, tab=30 mm,
                                      screw=0, rotation=90 deg,
                                      cx=s * (W / 2 - br_in), cy=shelf_top - br / 2)
        }
        hole screws {
            for p in [(-1, board_h - 12), (1, board_h - 12), (-1, 15), (1, 15)] {
                c = Circle(center=(p[0] * (W / 2 - 40 mm), p[1]), diameter=4.5)
            }
        }
        Countersink(screws.c, diameter=9 mm)
        drawing title {
            name = Text("HOLE SAWS", position=(0, (board_h + shelf_top) / 2), size=12,
                        valign="middle")
        }
    }

    solid shelf {
        # y = 0: the tabs' tips (flush with the board's back); the front edge at y = -80
        body = Rectangle(bottom_left=(-W / 2, -shelf_depth), width=W, height=shelf_depth)
        tabs = tab_and_slot(part="tab", length=W, thickness=t, tabs=2, tab=20 mm, screw=0,
                            cx=0 mm, cy=0 mm)
        hole slots {
            for i in range(len(saws)) {
                u = Slot(start=(saw_x(i), -t - reach), end=(saw_x(i), -shelf_depth - 10), width=12)
            }
        }
        for s in [-1, 1] {
            br_mortise = tab_and_slot(part="slot", length=br, thickness=t, tabs=1, tab=30 mm,
                                      screw=0, rotation=90 deg,
                                      cx=s * (W / 2 - br_in), cy=-br / 2)
        }
        drawing sizes {
            for i in range(len(saws)) {
                label = Text(str(saws[i]), position=(saw_x(i), -t - 20), size=7, valign="middle")
            }
        }
    }

    left_bracket = bracket()
    right_bracket = bracket()

    # flat on the sheet: shelf under the board, brackets under the shelf
    Below(shelf, board, gap=10)
    Below(left_bracket, shelf, gap=10)
    AlignLeft(left_bracket, shelf)
    RightOf(right_bracket, left_bracket, gap=10)
    AlignTop(right_bracket, left_bracket)

    # in 3D: the board's engraved face to the front, its back face at y = 0
    Place(board, position=(0, 0, 0), face="front", up="up")
    Place(shelf, position=(0, 0, shelf_top - t), face="up", up="back")
    Place(left_bracket, position=(-(W / 2 - br_in) + t / 2, 0, shelf_top), face="left", up="up")
    Place(right_bracket, position=(W / 2 - br_in + t / 2, 0, shelf_top), face="left", up="up")

    # the request's own numbers
    assert len(saws) == 8, "eight saws"
    assert saw_x(1) - saw_x(0) - (19 + 25) / 2 == 6 mm, "6 mm between neighbouring saws"
    assert saw_x(7) - saw_x(6) - (57 + 64) / 2 == 6 mm, "6 mm between the two largest"
    assert saw_x(0) - 19 / 2 - (-W / 2) == 20 mm, "outer saw 20 mm from the end"
    assert W / 2 - (saw_x(7) + 64 / 2) == 20 mm, "outer saw 20 mm from the other end"
    assert reach - 64 / 2 > 0 mm, "the largest saw clears the board"
    assert board.body.bb.height == 140 mm
    assert shelf.body.bb.height == 80 mm
    assert board.body.bb.top - shelf_top == 30 mm
}
