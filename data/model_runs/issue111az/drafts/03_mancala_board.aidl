# Request: a travel mancala (kalah) board from 3 mm ply that comes apart into two halves for
# the games bag. Overall 390 x 110 mm with 15 mm rounded outer corners, two layers glued:
# a top layer with 12 round pits 36 mm across (2 rows of 6; 42 mm between pit centres along
# a row, rows 44 mm apart; the two middle columns 64 mm apart so the joint has room) and a
# 36 x 90 mm store at each end (centres 162 mm from the middle), on a plain bottom layer.
# Each layer is split in the middle; the halves lock with a sliding dovetail of 3 tails,
# 8 mm deep, 0.1 mm clearance. "PLAYER 1" engraved along the left half's near edge and
# "PLAYER 2" on the right half's far edge, facing the other player.

thickness 3 mm

import "std/joints.aidl"

half_len = 195 mm
board_h = 110 mm
corner = 15 mm
pit_d = 36 mm
pitch = 42 mm
row_gap = 44 mm
mid = 32 mm          # first pit centre from the seam
store_x = 162 mm
joint_d = 8 mm

def left_half(pits=true) -> solid {
    # the tail half reaches across the joint's band (x 0 .. 8)
    body = RoundedRectangle(bottom_left=(-half_len, -board_h / 2), width=half_len + joint_d,
                            height=board_h, corner_radii=[corner, 0, 0, corner])
    tails = dovetail(part="tail", length=board_h, depth=joint_d, tails=3, angle=10 deg,
                     clearance=0.1 mm, rotation=-90 deg, cx=0 mm, cy=0 mm)
    if pits {
        hole pit {
            c = Circle(center=(-mid - 2 * pitch, -row_gap / 2), diameter=pit_d)
        }
        grid = GridPattern(pit, 2, 3, (pitch, row_gap))
        hole store {
            s = Slot(center=(-store_x, 0), length=90 mm, width=36 mm, rotation=90 deg)
        }
        drawing label {
            name = Text("PLAYER 1", position=(-half_len / 2, -(board_h / 2 + row_gap / 2 + pit_d / 2) / 2),
                        size=6 mm, valign="middle")
        }
    }
}

def right_half(pits=true) -> solid {
    body = RoundedRectangle(bottom_left=(0, -board_h / 2), width=half_len, height=board_h,
                            corner_radii=[0, corner, corner, 0])
    sockets = dovetail(part="socket", length=board_h, depth=joint_d, tails=3, angle=10 deg,
                       clearance=0.1 mm, rotation=-90 deg, cx=0 mm, cy=0 mm)
    if pits {
        hole pit {
            c = Circle(center=(mid, -row_gap / 2), diameter=pit_d)
        }
        grid = GridPattern(pit, 2, 3, (pitch, row_gap))
        hole store {
            s = Slot(center=(store_x, 0), length=90 mm, width=36 mm, rotation=90 deg)
        }
        drawing label {
            name = Text("PLAYER 2", position=(half_len / 2, (board_h / 2 + row_gap / 2 + pit_d / 2) / 2),
                        size=6 mm, valign="middle", rotation=180 deg)
        }
    }
}

assembly mancala {
    top_l = left_half(pits=true)
    top_r = right_half(pits=true)
    base_l = left_half(pits=false)
    base_r = right_half(pits=false)

    # flat on the sheet, apart
    RightOf(top_r, top_l, gap=5 mm)
    AlignBottom(top_r, top_l)
    Below(base_l, top_l, gap=5 mm)
    AlignLeft(base_l, top_l)
    RightOf(base_r, base_l, gap=5 mm)
    AlignBottom(base_r, base_l)

    # in 3D: joined, the pitted layer on the plain one
    Place(base_l, position=(0, 0, 0))
    Place(base_r, position=(0, 0, 0))
    Place(top_l, position=(0, 0, 3 mm))
    Place(top_r, position=(0, 0, 3 mm))

    # the request's numbers
    assert top_l.body.bb.width - joint_d + top_r.body.bb.width == 390 mm, "390 long overall"
    assert top_l.body.bb.height == 110 mm and top_r.body.bb.height == 110 mm, "110 wide"
    assert len(top_l.grid) + len(top_r.grid) == 12, "12 pits"
    assert top_l.pit.c.diameter == 36 mm, "36 mm pits"
    assert top_r.grid[1].c.center.x - top_r.grid[0].c.center.x == 42 mm, "42 mm pitch"
    assert top_r.grid[3].c.center.y - top_r.grid[0].c.center.y == 44 mm, "rows 44 apart"
    assert top_r.pit.c.center.x - top_r.body.bb.left == 32 mm, "middle columns 64 apart"
    assert top_r.store.s.center.x - top_r.body.bb.left == 162 mm, "store 162 from the middle"
    assert top_r.store.s.length == 90 mm and top_r.store.s.width == 36 mm, "36 x 90 stores"
    # the pits keep a 5 mm wall to the joint
    assert top_r.pit.c.center.x - pit_d / 2 - top_r.sockets.bb.right >= 5 mm, "wall to the sockets"
    assert top_l.tails.bb.left - (top_l.grid[2].c.center.x + pit_d / 2) >= 5 mm, "wall to the tails"
}
