# Request: a wall hat rack for the hall, cut from 6 mm birch ply. A backboard 420 x 110 mm
# with 10 mm rounded corners; three pegs 105 mm apart (centred on the board), their centres
# 15 mm below the board's middle, each standing out 90 mm in front of the board, 25 mm tall
# at the wall and ending in a 30 mm round knob so a cap cannot slide off; each peg is glued
# into a 6 x 20 mm mortise right through the board by a 20 mm tenon. Two keyholes (8 mm
# head, 4 mm slot, 10 mm long, slot pointing up) 40 mm in from each end and 30 mm below the
# top, to hang it on two screws. "HATS & CAPS" engraved in 10 mm capitals, centred, above
# the pegs.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

param board_w = 420 mm, min = 300 mm, max = 600 mm
param board_h = 110 mm, min = 90 mm, max = 160 mm
param pitch = 105 mm, min = 80 mm, max = 140 mm
param reach = 90 mm, min = 60 mm, max = 120 mm
peg_h = 25 mm
knob_d = 30 mm
tenon = 20 mm
peg_y = -15 mm

# a peg drawn in its own plane: the wall end on x = 0 (the tenon), standing out toward +x
def peg() -> solid {
    root = Rectangle(bottom_left=(0, -peg_h / 2), width=10, height=peg_h, construction=true)
    knob = Circle(center=(6 + reach - knob_d / 2, 5), diameter=knob_d, construction=true)
    arm = Hull(root, knob)
    # one tenon 20 mm tall, 6 mm long (the board's thickness), on the wall edge
    t = tab_and_slot(part="tab", length=peg_h, thickness=6 mm, tabs=1, tab=tenon, screw=0,
                     rotation=90 deg, cx=0 mm, cy=0 mm)
}

assembly hat_rack {
    solid board {
        plate = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=10)
        for i in range(3) {
            m = tab_and_slot(part="slot", length=peg_h, thickness=6 mm, tabs=1, tab=tenon,
                             screw=0, rotation=90 deg, cx=(i - 1) * pitch, cy=peg_y)
        }
        left_key = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                           cx=-board_w / 2 + 40 mm, cy=board_h / 2 - 30 mm)
        right_key = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                            cx=board_w / 2 - 40 mm, cy=board_h / 2 - 30 mm)
        drawing label {
            t = Text("HATS & CAPS", position=(0, 22), size=10, valign="middle")
        }
        Fixed(plate)
        AlignCenterX(label, plate)
    }

    for i in range(3) {
        p = peg()
        # stood out from the board's front face, the knob rising at the far end
        Place(p, position=((i - 1) * pitch + 3 mm, 0, peg_y), face="left", up="up")
    }

    # on the sheet: the pegs in a row under the board
    Below(p[0], board, gap=10)
    AlignLeft(p[0], board)
    for i in range(1, 3) {
        RightOf(p[i], p[i - 1], gap=10)
        AlignTop(p[i], p[i - 1])
    }

    assert len(p) == 3, "three pegs"
    assert board.plate.bb.width == 420 mm and board.plate.bb.height == 110 mm, "board 420 x 110"
    assert p[0].bb.width == 90 mm + 6 mm, "a peg stands out 90 mm in front of the 6 mm board"
    assert board.m[1].slot[0].bb.center_x - board.m[0].slot[0].bb.center_x == 105 mm, "pegs 105 mm apart"
    assert board.m[1].slot[0].bb.width == 6 mm and board.m[1].slot[0].bb.height == 20 mm, "6 x 20 mortise"
    assert board.plate.bb.center_y - board.m[1].slot[0].bb.center_y == 15 mm, "pegs 15 mm below the middle"
    assert board.plate.bb.top - board.left_key.head_hole.center.y == 30 mm, "keyholes 30 mm below the top"
    assert board.left_key.head_hole.center.x - board.plate.bb.left == 40 mm, "keyholes 40 mm in"
    assert board.label.bb.bottom > board.m[1].slot[0].bb.top, "label above the pegs"
}
