# Request (parties): "A balloon-pop dart game for a garden party. A 600 x 450 mm backboard of
# 6 mm ply with a grid of 4 rows x 5 columns of balloon mounts, 110 mm apart across and 100 mm
# apart up; each mount is a keyhole (10 mm head, 4 mm slot running 10 mm up) that grips the
# balloon's knot. Under each mount engrave its score: 10 on the bottom row, then 20, 50 and 100
# on the top row. Across the top, POP A BALLOON in 30 mm bold capitals, engraved filled. It
# stands on two triangular feet, 250 mm deep and 200 mm tall, glued in with two 40 mm tabs
# each through mortises 25 mm in from the board's sides."

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

param board_w = 600 mm, min = 500 mm, max = 800 mm
param board_h = 450 mm, min = 400 mm, max = 600 mm
param col_pitch = 110 mm, min = 90 mm, max = 130 mm
param row_pitch = 100 mm, min = 80 mm, max = 110 mm
param foot_d = 250 mm, min = 180 mm, max = 320 mm
param foot_h = 200 mm, min = 150 mm, max = 250 mm

scores = [10, 20, 50, 100]
rows = 4
cols = 5
# the grid's bottom-left mount
x0 = -(cols - 1) * col_pitch / 2
y0 = -180 mm
mortise_x = board_w / 2 - 25 mm

def foot() -> solid {
    body = Polygon([(0, 0), (foot_d, 0), (foot_d, 15 mm), (30 mm, foot_h), (0, foot_h)])
    # the upright edge (x = 0) carries two tabs that pass through the board
    tabs = tab_and_slot(part="tab", length=foot_h, thickness=6 mm, tabs=2, tab=40 mm,
                        screw=0, rotation=90 deg, cx=0 mm, cy=foot_h / 2)
}

assembly balloon_game {
    solid board {
        body = Rectangle(center=(0, 0), width=board_w, height=board_h)
        mount = keyhole(head=10 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                        cx=x0, cy=y0)
        mounts = GridPattern(mount, rows, cols, (col_pitch, row_pitch))
        left_mortise = tab_and_slot(part="slot", length=foot_h, thickness=6 mm, tabs=2,
                                    tab=40 mm, screw=0, rotation=90 deg,
                                    cx=-mortise_x, cy=-board_h / 2 + foot_h / 2)
        right_mortise = tab_and_slot(part="slot", length=foot_h, thickness=6 mm, tabs=2,
                                     tab=40 mm, screw=0, rotation=90 deg,
                                     cx=mortise_x, cy=-board_h / 2 + foot_h / 2)
        drawing points {
            for r in range(rows) {
                for c in range(cols) {
                    p = Text(str(scores[r]), position=(x0 + c * col_pitch, y0 + r * row_pitch - 16 mm),
                             size=8, valign="middle")
                }
            }
        }
        drawing title {
            t = Text("POP A BALLOON", position=(0, board_h / 2 - 40 mm), size=30,
                     font="sans:Bold", fill=true, valign="middle")
        }
    }
    left_foot = foot()
    right_foot = foot()

    # flat layout: feet to the right of the board
    RightOf(left_foot, board, gap=10 mm)
    AlignBottom(left_foot, board)
    Above(right_foot, left_foot, gap=10 mm)
    AlignLeft(right_foot, left_foot)

    # assembled: the board upright facing the front, the feet behind it, tabs through it
    Place(board, position=(0, 0, board_h / 2), face="front", up="up")
    Place(left_foot, position=(-mortise_x - 3 mm, -6 mm, 0), face="right", up="up")
    Place(right_foot, position=(mortise_x - 3 mm, -6 mm, 0), face="right", up="up")

    assert board.body.bb.width == 600 mm and board.body.bb.height == 450 mm, "600 x 450 board"
    assert len(board.mounts) == 20, "4 x 5 mounts"
    assert board.mounts[1].head_hole.center.x - board.mounts[0].head_hole.center.x == 110 mm, "110 mm across"
    assert board.mounts[5].head_hole.center.y - board.mounts[0].head_hole.center.y == 100 mm, "100 mm up"
    assert board.points.p[0][0].text == "10" and board.points.p[3][4].text == "100", "scores 10 at the bottom, 100 at the top"
    assert board.body.bb.right - board.right_mortise.slot[0].bb.center_x == 25 mm, "mortises 25 mm in"
    assert left_foot.body.bb.width == 250 mm and left_foot.body.bb.height == 200 mm, "feet 250 deep, 200 tall"
    assert distance(board.title, board.mounts) >= 10 mm, "title clear of the top row"
    assert distance(board.points, board.left_mortise) >= 5 mm, "scores clear of the mortises"
}
