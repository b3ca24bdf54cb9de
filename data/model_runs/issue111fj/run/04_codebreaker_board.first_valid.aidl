# Request: a peg board for the code-breaking game (like Mastermind), 3 mm ply, two layers
# glued together so the pegs sit in blind holes. Board 100 x 260 mm, corners R8.
# Ten guess rows 18 mm apart, the first 65 mm below the board's centre: in each four 6.5 mm
# code-peg holes at x = -36, -22, -8, 6 (14 mm pitch) and, centred at x = 30, a 2 x 2
# cluster of 3.2 mm key-peg holes 8 mm apart; each row numbered 1-10 at x = -45 (4 mm).
# At the top the secret row: four 6.5 mm holes 120 mm above the centre, hidden by a
# removable shield 80 x 28 mm standing on two 10 mm tenons in slots (0.2 mm clearance)
# 108.5 mm above the centre; "SECRET CODE" engraved on the shield.
# At the bottom two peg wells 40 x 30 (R5) cut in the top layer, centred 95 mm below the
# centre and 22 mm either side, and "CODE BREAKER" engraved 122 mm below the centre.

units mm
thickness 3 mm

import "std/joints.aidl"

T = 3 mm
BOARD_W = 100 mm
BOARD_H = 260 mm
ROWS = 10
PITCH = 18 mm
ROW1_Y = -65 mm
CODE_X = [-36 mm, -22 mm, -8 mm, 6 mm]
KEY_X = 30 mm
KEYS = [(-4 mm, -4 mm), (4 mm, -4 mm), (-4 mm, 4 mm), (4 mm, 4 mm)]
SECRET_Y = 120 mm
SHIELD_Y = 108.5 mm

assembly codebreaker {
    solid top_layer {
        body = RoundedRectangle(center=(0, 0), width=BOARD_W, height=BOARD_H, corner_radius=8)
        hole code {
            for r in range(ROWS) {
                for c in range(4) {
                    h = Circle(center=(CODE_X[c], ROW1_Y + r * PITCH), diameter=6.5 mm)
                }
            }
        }
        hole keys {
            for r in range(ROWS) {
                for k in range(4) {
                    h = Circle(center=(KEY_X + KEYS[k][0], ROW1_Y + r * PITCH + KEYS[k][1]), diameter=3.2 mm)
                }
            }
        }
        hole secret {
            for c in range(4) {
                h = Circle(center=(CODE_X[c], SECRET_Y), diameter=6.5 mm)
            }
        }
        hole wells {
            for s in [-1, 1] {
                w = RoundedRectangle(center=(s * 22 mm, -95 mm), width=40, height=30, corner_radius=5)
            }
        }
        shield_slot = tab_and_slot(part="slot", length=80 mm, thickness=T, tabs=2, tab=10 mm,
                                   screw=0, clearance=0.2 mm, cx=0, cy=SHIELD_Y)
        drawing numbers {
            for r in range(ROWS) {
                n = Text(str(r + 1), position=(-45 mm, ROW1_Y + r * PITCH), size=4, valign="middle")
            }
            title = Text("CODE BREAKER", position=(0, -122 mm), size=6)
        }
        assert len(code.h) == 10 and len(code.h[0]) == 4, "ten rows of four"
        assert code.h[1][0].center.y - code.h[0][0].center.y == 18 mm, "rows 18 apart"
        assert code.h[0][1].center.x - code.h[0][0].center.x == 14 mm, "pegs 14 apart"
        assert body.bb.width == 100 mm and body.bb.height == 260 mm, "board 100 x 260"
    }

    solid bottom_layer {
        body = RoundedRectangle(center=(0, 0), width=BOARD_W, height=BOARD_H, corner_radius=8)
    }

    solid shield {
        body = Rectangle(bottom_left=(-40 mm, -T), width=80 mm, height=28 mm + T)
        tenons = tab_and_slot(part="tab", length=80 mm, thickness=T, tabs=2, tab=10 mm,
                              screw=0, rotation=180 deg, cx=0, cy=-T)
        drawing label {
            t = Text("SECRET CODE", position=(0, 14 mm), size=6, valign="middle")
        }
        assert body.bb.height - T == 28 mm, "shield 28 high"
    }

    # flat layout
    RightOf(bottom_layer, top_layer, gap=10)
    AlignTop(bottom_layer, top_layer)
    RightOf(shield, bottom_layer, gap=10)
    AlignTop(shield, bottom_layer)

    # 3D: the two layers stacked, the shield standing in its slots
    Place(bottom_layer, position=(0, 0, 0), face="up")
    Place(top_layer, position=(0, 0, T), face="up")
    Place(shield, position=(0, SHIELD_Y + T / 2, 2 * T), face="front", up="up")
}
