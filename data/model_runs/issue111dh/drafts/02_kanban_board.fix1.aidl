# Request (office): a desk kanban board, 3 mm birch ply.
# Upright board 300 wide x 210 tall, R8 on the two top corners, square bottom corners to stand on.
# Three columns 100 wide headed "TO DO", "DOING", "DONE": bold letters 10 mm tall, filled
# engraving, their middle 16 mm below the top edge, each centred on its column. The columns are
# divided by engraved lines from 30 mm below the top edge to 10 mm above the bottom.
# In each column three slits 70 mm long, centred on the column, at 55, 105 and 155 mm below the top
# edge, to tuck index cards into. Two right-triangle feet behind it, 80 deep x 120 tall, standing
# on the column dividers, each glued with two 15 mm tabs into mortises in the board.

units mm
thickness 3 mm

import "std/joints.aidl"

board_w = 300 mm
board_h = 210 mm
col_w = 100 mm
foot_d = 80 mm
foot_h = 120 mm
heads = ["TO DO", "DOING", "DONE"]

def foot() -> solid {
    tri = Polygon([(0, 0), (foot_d, 0), (0, foot_h)])
    # tabs on the upright edge (x = 0), the foot toward +x
    j = tab_and_slot(part="tab", length=foot_h, thickness=3 mm, tabs=2, tab=15 mm, screw=0,
                     rotation=90 deg, cx=0, cy=foot_h / 2)
}

assembly kanban {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=board_w, height=board_h,
                                corner_radii=[8, 8, 0, 0])
        for s in [-1, 1] {
            m = tab_and_slot(part="slot", length=foot_h, thickness=3 mm, tabs=2, tab=15 mm,
                             screw=0, rotation=90 deg, cx=s * col_w / 2,
                             cy=-board_h / 2 + foot_h / 2)
        }
        cut slits {
            for c in range(3) {
                for r in range(3) {
                    s = Line(((c - 1) * col_w - 35, board_h / 2 - 55 - 50 * r),
                             ((c - 1) * col_w + 35, board_h / 2 - 55 - 50 * r))
                }
            }
        }
        drawing face {
            for c in range(3) {
                head = Text(heads[c], position=((c - 1) * col_w, board_h / 2 - 16), size=10,
                            font="sans:Bold", valign="middle", fill=true)
            }
            for s in [-1, 1] {
                divider = Line((s * col_w / 2, board_h / 2 - 30), (s * col_w / 2, -board_h / 2 + 10))
            }
        }
        # FIX after the first valid program: W0505 accepted, not a defect: the dividers run
        # the requested length and cross the feet's mortises on purpose (the tab ends fill them)
        AllowOverlap(face.divider, self)
    }
    left_foot = foot()
    right_foot = foot()

    # flat on the sheet: the feet beside the board
    RightOf(left_foot, board, gap=10)
    RightOf(right_foot, left_foot, gap=10)
    AlignBottom(left_foot, board)
    AlignBottom(right_foot, board)

    # standing: the board upright facing the front, the feet behind it on the dividers,
    # their tab tips flush with the board's front face
    Place(board, position=(0, 0, board_h / 2), face="front", up="up")
    Place(left_foot, position=(-col_w / 2 - 1.5, -3, 0), face="right", up="up")
    Place(right_foot, position=(col_w / 2 - 1.5, -3, 0), face="right", up="up")

    # the request's numbers
    assert board.body.bb.width == 300 mm and board.body.bb.height == 210 mm, "board 300 x 210"
    assert len(board.face.head) == 3, "three columns"
    assert board.body.bb.top - board.face.head[0].position.y == 16 mm, "headers 16 below the top"
    assert board.face.head[1].position.x - board.face.head[0].position.x == 100 mm, "columns 100 wide"
    assert board.slits.s[0][0].length == 70 mm, "slits 70 long"
    assert board.body.bb.top - board.slits.s[0][2].start.y == 155 mm, "last slit 155 below the top"
    assert left_foot.tri.bb.width == 80 mm and left_foot.tri.bb.height == 120 mm, "feet 80 x 120"
}
