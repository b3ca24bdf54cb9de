# Request (garden): a row-end stake that holds the seed packet, so I know what is in the row.
# 6 mm exterior ply, two parts:
# - a board 110 x 160 mm on a 30 mm wide stake that runs 250 mm below the board to a 60 degree
#   point; four 20 mm slits at the corners of a 92 x 128 mm seed packet centred on the board,
#   each across the packet's corner diagonal, 6 mm in from the corner, to tuck its corners in;
# - a 130 x 50 mm rain hood (front corners R10) glued on top of the board, overhanging it 10 mm
#   each side, its back edge 10 mm behind the board's middle, held by two 10 mm tabs from the
#   board's top edge in closed slots (0.1 mm clearance); "ROW 3" engraved filled on the hood,
#   bold sans, 12 mm tall, centred in front of the board.

import "std/joints.aidl"

thickness 6 mm

param clear = 0.1 mm, min = 0 mm, max = 0.3 mm

board_w = 110 mm
board_h = 160 mm
stake_w = 30 mm
stake_len = 250 mm
packet_w = 92 mm
packet_h = 128 mm
inset = 6 mm / sqrt(2)       # 6 mm in along the diagonal, per axis
sx = [1, -1, -1, 1]
sy = [1, 1, -1, -1]
tip = 15 mm / tan(30 deg)    # a 60 degree point on a 30 mm stake

assembly marker {
    solid board {
        plate = Rectangle(bottom_left=(-55, 0), width=110, height=166)   # 6 mm of it becomes the tabs
        stake = Polygon([(-15, 1), (15, 1), (15, -250 + tip), (0, -250), (-15, -250 + tip)])
        top_tabs = tab_and_slot(part="tab", length=110 mm, thickness=6 mm, tabs=2, tab=10 mm,
                                screw=0, cx=0 mm, cy=166 mm)
        cut slits {
            for i in range(4) {
                s = Line(start=(sx[i] * (46 mm - inset) - sx[i] * 10 mm / sqrt(2),
                                80 mm + sy[i] * (64 mm - inset) + sy[i] * 10 mm / sqrt(2)),
                         length=20, angle=atan2(-sy[i], sx[i]))
            }
        }
    }
    solid hood {
        roof = RoundedRectangle(center=(0, 0), width=130, height=50, corner_radii=[0, 0, 10, 10])
        slots = tab_and_slot(part="slot", length=110 mm, thickness=6 mm, tabs=2, tab=10 mm,
                             screw=0, clearance=clear, cx=0 mm, cy=15 mm)
        drawing label {
            t = Text("ROW 3", position=(0, -7), size=12, font="sans:Bold", valign="middle", fill=true)
        }
    }

    # on the sheet
    RightOf(hood, board, gap=5)
    AlignTop(hood, board)

    # in 3D: the board upright facing the front, the hood on its top edge
    Place(board, position=(0, 0, 0), face="front", up="up")
    Place(hood, position=(0, -3 - 15, 160), face="up", up="back")

    # the request's numbers
    assert board.plate.bb.width == 110 mm and board.plate.bb.height - 6 mm == 160 mm, "board 110 x 160"
    assert board.stake.bb.width == 30 mm, "stake 30 wide"
    assert 0 mm - board.stake.bb.bottom == 250 mm, "stake 250 below the board"
    assert len(board.slits.s) == 4, "four slits"
    assert board.slits.s[0].length == 20 mm, "slits 20 long"
    # each slit crosses its packet corner's diagonal 6 mm in: its middle is on the diagonal
    assert distance(board.slits.s[0].midpoint, Point(46, 80 + 64)) == 6 mm, "slit 6 in from the corner"
    assert hood.roof.bb.width - board.plate.bb.width == 2 * 10 mm, "hood overhangs 10 each side"
    assert hood.roof.bb.top - hood.slots.cy == 10 mm, "hood's back 10 behind the board's middle"
    assert hood.label.bb.top < hood.slots.slot[0].bb.bottom - 2 mm, "label in front of the board"
    # the packet fits the board with room round it
    assert packet_w < board_w - 10 mm and packet_h < board_h - 10 mm, "packet fits"
}
