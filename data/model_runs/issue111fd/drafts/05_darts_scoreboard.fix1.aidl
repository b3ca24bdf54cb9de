# Request (sport): a wall scoreboard for darts "cricket", in 6 mm birch ply, chalked on.
# Board 300 wide x 420 high with 10 mm corners, hung on two keyholes (8 mm head, slot 10 mm up)
# 200 mm apart, 35 mm below the top edge. Engraved: "CRICKET" in filled bold letters 24 mm high
# across the top; "HOME" and "AWAY" 12 mm over the two player columns; a grid of 8 rows 30 mm
# high (20, 19, 18, 17, 16, 15, BULL, PTS in filled letters 14 mm high in a 74 mm middle
# column, a 108 mm chalk column each side), its top line 100 mm above the board's centre, the
# grid 290 wide. A chalk ledge 50 mm deep in front of the board, 300 wide, glued into the board
# by three 40 mm through-tenons 30 mm above the bottom edge, with a 15 mm lip along its front
# (three 40 mm tenons down into the ledge), six 6 mm holes 20 mm apart in its right half to
# stand darts in, and "CHALK" engraved on its left half.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

T = 6 mm
W = 300 mm
H = 420 mm
ROW = 30 mm
GRID_TOP = 100 mm
MID = 74 mm
LEDGE = 50 mm
LIP = 15 mm
LIP_BACK = 3 mm
LABELS = ["20", "19", "18", "17", "16", "15", "BULL", "PTS"]

solid_w = W

def board_part() -> solid {
    body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=10)
    for s in [-1, 1] {
        hang = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                       cx=s * 100 mm, cy=H / 2 - 35 mm)
    }
    ledge_slots = tab_and_slot(part="slot", length=W, thickness=T, tabs=3, tab=40 mm, screw=0,
                               cx=0, cy=-H / 2 + 30 mm)
    drawing face {
        title = Text("CRICKET", position=(0, 150), size=24, font="sans:Bold", fill=true)
        home = Text("HOME", position=(-(MID / 2 + 54 mm), GRID_TOP + 12), size=12,
                    font="sans:Bold", valign="middle", fill=true)
        away = Text("AWAY", position=(MID / 2 + 54 mm, GRID_TOP + 12), size=12,
                    font="sans:Bold", valign="middle", fill=true)
        for k in range(9) {
            rule = Line((-145, GRID_TOP - k * ROW), (145, GRID_TOP - k * ROW))
        }
        for x in [-145, -MID / 2, MID / 2, 145] {
            col = Line((x, GRID_TOP), (x, GRID_TOP - 8 * ROW))
        }
        for k in range(8) {
            label = Text(LABELS[k], position=(0, GRID_TOP - ROW / 2 - k * ROW), size=14,
                         font="sans:Bold", valign="middle", fill=true)
        }
    }
}

def ledge_part() -> solid {
    # 50 mm in front of the board plus the tenons through it; the back edge at y = +28
    body = Rectangle(center=(0, 0), width=W, height=LEDGE + T)
    tenons = tab_and_slot(part="tab", length=W, thickness=T, tabs=3, tab=40 mm, screw=0,
                          cx=0, cy=(LEDGE + T) / 2)
    # FIX after the first valid program: the lip's mortises sat on the front edge (W0530, real:
    # open notches); the lip now stands 3 mm back from the ledge's front edge
    lip_slots = tab_and_slot(part="slot", length=W, thickness=T, tabs=3, tab=40 mm, screw=0,
                             cx=0, cy=-(LEDGE + T) / 2 + LIP_BACK + T / 2)
    hole darts {
        for i in range(6) {
            d = Circle(center=(40 + i * 20, 0), diameter=6)
        }
    }
    drawing word {
        chalk = Text("CHALK", position=(-80, 0), size=10, valign="middle")
    }
}

def lip_part() -> solid {
    body = Rectangle(center=(0, 0), width=W, height=LIP + T)
    tenons = tab_and_slot(part="tab", length=W, thickness=T, tabs=3, tab=40 mm, screw=0,
                          rotation=180 deg, cx=0, cy=-(LIP + T) / 2)
}

assembly scoreboard {
    board = board_part()
    ledge = ledge_part()
    lip = lip_part()
    # the board's front face at y = 0, its centre 300 mm up
    Place(board, position=(0, T, 300 mm), face="front", up="up")
    # the ledge level, its tenons' tips flush with the board's back face, mid-thickness on the
    # board's slot line (30 mm above the bottom edge)
    Place(ledge, position=(0, T - (LEDGE + T) / 2, 300 mm - H / 2 + 30 mm - T / 2),
          face="up", up="back")
    # the lip standing on the ledge's front edge, its tenons down through the ledge
    Place(lip, position=(0, T - (LEDGE + T) / 2 - (LEDGE + T) / 2 + LIP_BACK + T,
                         300 mm - H / 2 + 30 mm - T / 2 + (LIP + T) / 2), face="front", up="up")

    # flat on the sheet
    Below(ledge, board, gap=10)
    AlignLeft(ledge, board)
    Below(lip, ledge, gap=10)
    AlignLeft(lip, ledge)

    assert board.body.bb.width == 300 mm and board.body.bb.height == 420 mm, "board 300 x 420"
    assert board.hang[1].head_hole.center.x - board.hang[0].head_hole.center.x == 200 mm,
        "keyholes 200 apart"
    assert board.body.bb.top - board.hang[0].head_hole.center.y == 35 mm, "keyholes 35 down"
    assert len(board.face.label) == 8, "eight rows"
    assert board.face.rule[0].start.y - board.body.bb.center_y == 100 mm, "grid top 100 up"
    assert board.face.rule[0].start.y - board.face.rule[8].start.y == 8 * 30 mm, "rows 30 high"
    assert board.face.rule[0].end.x - board.face.rule[0].start.x == 290 mm, "grid 290 wide"
    assert board.face.col[2].start.x - board.face.col[1].start.x == 74 mm, "middle column 74"
    assert board.ledge_slots.slot[0].bb.center_y - board.body.bb.bottom == 30 mm,
        "ledge 30 mm above the bottom"
    assert ledge.body.bb.height - 6 mm == 50 mm, "ledge 50 deep in front of the board"
    assert lip.body.bb.height - 6 mm == 15 mm, "lip 15 high"
    assert len(ledge.darts.d) == 6, "six dart holes"
    assert ledge.darts.d[1].center.x - ledge.darts.d[0].center.x == 20 mm, "20 apart"
    assert ledge.darts.d[0].center.x > 0, "in the right half"
    assert distance(board.face.title, board.hang) >= 3 mm, "title clear of the keyholes"
    assert distance(board.face.rule[8], board.ledge_slots) >= 5 mm, "grid clear of the ledge"
}
