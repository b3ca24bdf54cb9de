# Request: a hexagonal "honeycomb" wall shelf for small plants and trinkets, cut from 6 mm
# plywood. The back plate is a regular hexagon 240 mm across the corners, flats at top and
# bottom (the bottom flat is the shelf floor). Six side boards stand on it all round, their
# outer faces flush with the plate's edge, so the shelf is 100 mm deep overall (6 mm plate +
# 94 mm of board). Each board has two 20 mm tabs on its back edge glued into mortises in the
# plate (0.1 mm clearance); the boards meet at their inner corners (glued, a small V at each
# outer corner). Two keyholes for 4 mm screws (9 mm heads), 80 mm apart, hang it on the wall.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

t = 6 mm                     # plywood
across_corners = 240 mm
depth = 100 mm               # overall, wall to front edge
side = across_corners / 2                  # a regular hexagon's side = its corner radius
apothem = side * cos(30 deg)               # centre to the middle of a flat
# FIX after the first valid program: W0530 said each mortise ran out through the plate's edge
# (boards flush with the edge leave no material outside their mortises): the boards now stand
# `reveal` in from the plate's edge, leaving 4.95 mm of plate outside each mortise.
reveal = 5 mm
face_r = apothem - reveal                  # centre to a board's outer face
board_len = 2 * (face_r - t) * tan(30 deg) # the board's length at its inner face
board_h = depth                            # 94 mm showing + 6 mm of tabs in the plate

def side_board() -> solid {
    body = Rectangle(center=(0, 0), width=board_len, height=board_h)
    # tabs on the back (bottom) edge, the panel above the edge
    tabs = tab_and_slot(part="tab", length=board_len, thickness=t, tabs=2, tab=20 mm,
                        screw=0, rotation=180 deg, cx=0 mm, cy=-board_h / 2)
}

assembly hex_shelf {
    solid back {
        hexagon = RegularPolygon(center=(0, 0), radius=side, sides=6)
        for i in range(6) {
            # mortises under the middle of board i, which stands along flat i
            mortise = tab_and_slot(part="slot", length=board_len, thickness=t, tabs=2,
                                   tab=20 mm, screw=0, clearance=0.1 mm,
                                   rotation=60 * i + 120 deg,
                                   cx=(face_r - t / 2) * cos(60 * i + 30 deg),
                                   cy=(face_r - t / 2) * sin(60 * i + 30 deg))
        }
        hang_l = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, cx=-40 mm, cy=50 mm)
        hang_r = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, cx=40 mm, cy=50 mm)
    }
    Place(back, position=(0, 0, 0), face="front", up="up")

    for i in range(6) {
        board = side_board()
        # laid out flat below the back plate, two rows of three
        board.bb.center == (-130 + 130 * (i % 3), -190 - 115 * (i // 3))
        # in 3D: standing on flat i, outer face outward, depth toward the front (-y)
        Place(board, position=((face_r - t) * cos(60 * i + 30 deg), -board_h / 2,
                               (face_r - t) * sin(60 * i + 30 deg)),
              face=(cos(60 * i + 30 deg), 0, sin(60 * i + 30 deg)), up="front")
    }

    assert back.hexagon.bb.width == 240 mm, "240 mm across the corners"
    assert len(board) == 6, "six side boards"
    assert t + (board[0].body.bb.height - t) == 100 mm, "100 mm deep overall: plate + board showing"
    assert back.hang_r.head_hole.center.x - back.hang_l.head_hole.center.x == 80 mm,
        "keyholes 80 mm apart"
}
