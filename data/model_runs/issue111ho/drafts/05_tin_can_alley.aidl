# Request (parties): a tabletop "tin can alley" for a garden party, 6 mm ply, knock-down.
# A backboard 580 x 380 mm with "TIN CAN ALLEY" cut through as 40 mm bold stencil
# letters centred 60 mm below its top; a shelf 560 x 120 mm for the cans, its top face
# 156 mm above the table, joined to the backboard by three 40 mm tabs with two M3 screws
# and captive nuts; under the shelf four 70 mm beanbag holes, 120 mm apart, centred 80 mm
# up, each with its score (10, 20, 30, 40) engraved 12 mm tall above it. The board stands
# on two 200 x 80 mm feet cross-halved into it 240 mm either side of the middle.

units mm
thickness 6 mm

import "std/joints.aidl"

board_w = 580 mm
board_h = 380 mm
shelf_top = 156 mm
foot_x = 240 mm

def foot() -> solid {
    body = Rectangle(center=(0, 40), width=200, height=80)
    slot = cross_halving(depth=40 mm, thickness=6 mm, rotation=0 deg, cx=0 mm, cy=80 mm)
}

assembly alley {
    solid board {
        body = Rectangle(center=(0, board_h / 2), width=board_w, height=board_h)
        hole letters {
            t = Text("TIN CAN ALLEY", (0, board_h - 60), size=40, font="sans:Bold",
                     stencil=true, valign="middle")
        }
        ledge = tab_and_slot(part="slot", length=560 mm, thickness=6 mm, tabs=3, tab=40 mm,
                             screw=3, rotation=0 deg, cx=0 mm, cy=shelf_top - 3 mm)
        hole target {
            c = Circle(center=(-180, 80), diameter=70)
        }
        targets = LinearPattern(target, 4, (120, 0))
        drawing scores {
            for i in range(4) {
                s = Text(str(10 * (i + 1)), (-180 + 120 * i, 130), size=12, font="sans:Bold",
                         fill=true, valign="middle")
            }
        }
        left_foot_slot = cross_halving(depth=40 mm, thickness=6 mm, rotation=180 deg,
                                       cx=-foot_x, cy=0 mm)
        right_foot_slot = cross_halving(depth=40 mm, thickness=6 mm, rotation=180 deg,
                                        cx=foot_x, cy=0 mm)
    }
    solid shelf {
        body = Rectangle(center=(0, 0), width=560, height=120)
        tabs = tab_and_slot(part="tab", length=560 mm, thickness=6 mm, tabs=3, tab=40 mm,
                            screw=3, rotation=0 deg, cx=0 mm, cy=60 mm)
    }
    left_foot = foot()
    right_foot = foot()

    Below(shelf, board, gap=10)
    AlignLeft(shelf, board)
    RightOf(left_foot, shelf, gap=10)
    AlignTop(left_foot, shelf)
    RightOf(right_foot, left_foot, gap=10)
    AlignTop(right_foot, shelf)

    Place(board, position=(0, 3, 0), face="front", up="up")
    Place(shelf, position=(0, -57, shelf_top - 6 mm))
    Place(left_foot, position=(-foot_x - 3 mm, 0, 0), face="right", up="up")
    Place(right_foot, position=(foot_x - 3 mm, 0, 0), face="right", up="up")

    assert board.body.bb.width == 580 mm and board.body.bb.height == 380 mm, "board 580 x 380"
    assert board.body.bb.top - board.letters.t.position.y == 60 mm, "letters 60 mm below the top"
    assert board.letters.bb.width <= board_w - 40 mm, "letters clear of the edges"
    assert len(board.targets) == 4, "four beanbag holes"
    assert board.target.c.diameter == 70 mm, "70 mm holes"
    assert board.targets[1].c.center.x - board.targets[0].c.center.x == 120 mm, "120 mm apart"
    assert board.target.c.center.y - board.body.bb.bottom == 80 mm, "holes 80 mm up"
    assert distance(board.targets, board.left_foot_slot) >= 10 mm, "holes clear of the foot slots"
    assert distance(board.scores, board.targets) >= 3 mm, "scores clear of their holes"
    assert distance(board.scores, board.ledge) >= 3 mm, "scores clear of the shelf slots"
    assert distance(board.letters, board.ledge) >= 10 mm, "letters clear of the shelf"
    assert shelf.body.bb.width == 560 mm and shelf.body.bb.height == 120 mm, "shelf 560 x 120"
    assert left_foot.body.bb.width == 200 mm and left_foot.body.bb.height == 80 mm, "feet 200 x 80"
}
