# Request: a tamper for firming compost in a full-size seed tray, 6 mm exterior ply.
# Board 330 x 200 mm, corners rounded R10, with 24 air holes 4 mm (4 rows x 6 columns,
# 50 mm pitch, centred; they stop the compost sticking). A handle stands on the middle of the
# board across its length: 200 mm long, 84 mm above the board (90 with the 6 mm tabs),
# straight sides 60 mm tall then an arched top, a 110 x 32 mm hand hole centred 45 mm up;
# glued into 3 mortises, tabs 25 mm wide. Along the front edge an engraved sowing rule:
# a tick every 10 mm over 300 mm (31 ticks, 4 mm long, every 5th one 8 mm with its number in
# cm, 0-30), and "FIRM, DON'T PACK" engraved near the back edge, 6 mm letters.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
board_w = 330 mm
board_d = 200 mm

assembly seed_tray_tamper {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=board_w, height=board_d, corner_radius=10)
        hole air {
            c = Circle(center=(-125, -75), diameter=4)
        }
        airs = GridPattern(air, rows=4, cols=6, spacing=(50, 50))
        mortise = tab_and_slot(part="slot", length=200 mm, thickness=t, tabs=3, tab=25 mm,
                               screw=0, cx=0 mm, cy=0 mm)
        drawing rule {
            for i in range(31) {
                tick = Line((-150 + i * 10, -board_d / 2 + 3),
                            (-150 + i * 10, -board_d / 2 + 3 + (8 if i % 5 == 0 else 4)))
            }
            for k in range(7) {
                num = Text(str(k * 5), position=(-150 + k * 50, -board_d / 2 + 14), size=4)
            }
        }
        drawing motto {
            m = Text("FIRM, DON'T PACK", position=(0, board_d / 2 - 14), size=6, valign="middle")
        }
    }

    solid handle {
        # frame: x along the handle, y up; y = 0 is the tabs' tips (the board's underside)
        bottom = Line((-100, 0), (100, 0))
        right = Line((100, 0), (100, 60))
        top = Arc(start=(100, 60), through=(0, 90), end=(-100, 60))
        left = Line((-100, 60), (-100, 0))
        hole grip {
            s = Slot(center=(0, 45), length=110, width=32)
        }
        tabs = tab_and_slot(part="tab", length=200 mm, thickness=t, tabs=3, tab=25 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=0 mm)
    }

    Above(handle, board, gap=10)
    AlignCenterX(handle, board)

    Place(board, position=(0, 0, 0), face="up")
    Place(handle, position=(0, t / 2, 0), face="front", up="up")

    # the request's numbers
    assert board.body.bb.width == 330 mm and board.body.bb.height == 200 mm, "board 330 x 200"
    assert len(board.airs) == 24, "24 air holes"
    assert board.airs[1].c.center.x - board.airs[0].c.center.x == 50 mm, "50 mm pitch"
    assert handle.bb.width == 200 mm, "handle 200 long"
    assert handle.top.through.y - handle.bottom.start.y == 90 mm, "handle 90 with its tabs"
    assert handle.right.end.y == 60 mm, "straight sides 60 tall"
    assert handle.grip.s.center.y - handle.bottom.start.y == 45 mm, "hand hole 45 up"
    assert len(board.rule.tick) == 31, "31 ticks"
    assert len(board.rule.num) == 7, "numbers 0-30"
}
