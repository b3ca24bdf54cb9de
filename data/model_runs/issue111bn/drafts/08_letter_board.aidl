# Request: a changeable letter board for the cafe counter, 3 mm plywood. A back board 320 x 240
# that hangs on two screws through keyholes (8 mm head, 4 mm slot 10 mm up) 135 mm either side
# of the centre, 100 mm above it; "TODAY" engraved filled in bold 18 mm letters across the top,
# centred 100 mm above the centre. Four ledges 300 long and 12 deep, 50 mm apart (the lowest
# 95 mm below the centre), glued into the board with three 30 mm tabs each. Letter tiles 22 x 30
# with r2 corners stand on the ledges against the board, each with its character engraved
# filled in bold 18 mm: A to Z, 0 to 9, &, -, . and a second E: 40 tiles, ten to a ledge.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 3 mm
T = 3 mm
BOARD_W = 320 mm
BOARD_H = 240 mm
ROWS = [-95 mm, -45 mm, 5 mm, 55 mm]    # ledge centres on the board
LEDGE_L = 300 mm
LEDGE_D = 12 mm
TILE_W = 22 mm
TILE_H = 30 mm
CHARS = ["A", "B", "C", "D", "E", "F", "G", "H", "I", "J", "K", "L", "M", "N", "O", "P", "Q",
         "R", "S", "T", "U", "V", "W", "X", "Y", "Z", "0", "1", "2", "3", "4", "5", "6", "7",
         "8", "9", "&", "-", ".", "E"]

def ledge() -> solid {
    # local: y = 0 the front edge, y = LEDGE_D the board's face, the tabs to LEDGE_D + T
    body = Rectangle(bottom_left=(-LEDGE_L / 2, 0), width=LEDGE_L, height=LEDGE_D + T)
    tabs = tab_and_slot(part="tab", length=LEDGE_L, thickness=T, tabs=3, tab=30 mm, screw=0,
                        cx=0, cy=LEDGE_D + T)
    Fixed(body)
}

def tile(ch="A", x=0 mm, y=0 mm) -> solid {
    body = RoundedRectangle(center=(x, y), width=TILE_W, height=TILE_H, corner_radius=2)
    drawing face {
        # FIX after the first valid program: at 18 mm the bold W (and nearly the M) is wider than
        # the 22 mm tile (W0505). First tried max_width=18 mm: it measures the advance width, so
        # M fell to 13.6 mm and W lower, a patchy set. Now every tile is set at 15 mm, one cap
        # height across the set, which the W fits with room to spare.
        t = Text(ch, position=(x, y), size=15, font="sans:Bold", valign="middle", fill=true)
    }
    Fixed(body)
}

assembly letterboard {
    solid board {
        panel = Rectangle(center=(0, 0), width=BOARD_W, height=BOARD_H)
        for r in range(4) {
            slots = tab_and_slot(part="slot", length=LEDGE_L, thickness=T, tabs=3, tab=30 mm,
                                 screw=0, cx=0, cy=ROWS[r])
        }
        left_hang = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=-135, cy=100)
        right_hang = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=135, cy=100)
        drawing title {
            t = Text("TODAY", position=(0, 100), size=18, font="sans:Bold", valign="middle",
                     fill=true)
        }
        Fixed(panel)
        assert panel.bb.width == 320 mm and panel.bb.height == 240 mm, "board 320 x 240"
        assert right_hang.head_hole.center.x - left_hang.head_hole.center.x == 270 mm,
            "keyholes 135 either side"
        assert left_hang.head_hole.center.y - panel.center.y == 100 mm, "keyholes 100 up"
        assert slots[1].bb.center_y - slots[0].bb.center_y == 50 mm, "ledges 50 apart"
        assert panel.center.y - slots[0].bb.center_y == 95 mm, "lowest ledge 95 below centre"
    }

    for r in range(4) {
        l = ledge()
        Place(l, rotation=(0, 0, 180 deg), position=(0, LEDGE_D + T, ROWS[r] - T / 2))
    }

    for i in range(len(CHARS)) {
        t = tile(ch=CHARS[i], x=200 mm + (i % 10) * 26 mm, y=-(i // 10) * 34 mm)
        # 3D: ten to a ledge, the top ledge first, standing against the board's face
        Place(t, rotation=(90 deg, 0, 180 deg),
              position=(-117 mm + (i % 10) * 26 mm + 200 mm + (i % 10) * 26 mm, T,
                        ROWS[3 - i // 10] + T / 2 + TILE_H / 2 + (i // 10) * 34 mm))
    }

    assert len(t) == 40, "40 tiles"
    assert len(l) == 4, "four ledges"
    assert l[0].body.bb.height - T == 12 mm, "ledges 12 deep"
    assert t[0].body.bb.width == 22 mm and t[0].body.bb.height == 30 mm, "tiles 22 x 30"

    # sheet: the ledges under the board, the tiles to its right (where they are written)
    Below(l[0], board, gap=6)
    AlignLeft(l[0], board)
    for r in range(3) {
        Below(l[r + 1], l[r], gap=6)
        AlignLeft(l[r + 1], l[r])
    }

    # 3D: the board upright, its face toward +y
    Place(board, rotation=(90 deg, 0, 180 deg), position=(0, 0, 0))
}
