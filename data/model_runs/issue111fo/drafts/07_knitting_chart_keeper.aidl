# Request: a knitting chart keeper in 3 mm ply. A board 320 x 240 mm (R8 corners) that
# stands upright on two feet 160 x 40 mm, cross-halved into the board's bottom edge 110 mm
# either side of the middle (the board's slots and the feet's slots 20 mm deep each,
# 0.1 mm clearance); "KNIT CHART" engraved filled (bold serif, 10 mm) with its middle
# 15 mm below the top edge. A line keeper 320 x 30 mm that sits on the chart (a steel sheet
# is glued on the board) with two 10.2 mm holes for 10 mm magnets, their centres 12 mm in
# from the ends, a 260 x 6 mm window (its middle 5 mm above the keeper's middle) to show one
# row, and an engraved scale under it: a tick every 10 mm from 0 to 250 (3 mm long, 6 mm
# every 50) with 3 mm numbers every 50.

import "std/joints.aidl"

thickness 3 mm

T = 3 mm
BW = 320 mm
BH = 240 mm
FOOT_H = 40 mm
HALF = 20 mm

def foot() -> solid {
    body = Rectangle(center=(0, 0), width=160, height=FOOT_H)
    slot = cross_halving(depth=HALF, thickness=T, clearance=0.1 mm, cx=0 mm, cy=FOOT_H / 2)
}

assembly chart_keeper {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=BW, height=BH, corner_radius=8)
        slot_l = cross_halving(depth=HALF, thickness=T, clearance=0.1 mm, rotation=180 deg,
                               cx=-110 mm, cy=-BH / 2)
        slot_r = cross_halving(depth=HALF, thickness=T, clearance=0.1 mm, rotation=180 deg,
                               cx=110 mm, cy=-BH / 2)
        drawing title {
            t = Text("KNIT CHART", position=(0, BH / 2 - 15 mm), size=10, font="serif:Bold",
                     valign="middle", fill=true)
        }
    }

    solid keeper {
        bar = Rectangle(center=(0, 0), width=BW, height=30)
        hole magnets {
            left = Circle(center=(-BW / 2 + 12 mm, 0), diameter=10.2)
            right = Circle(center=(BW / 2 - 12 mm, 0), diameter=10.2)
        }
        hole window {
            w = Rectangle(center=(0, 5), width=260, height=6)
        }
        drawing scale {
            for i in range(26) {
                tick = Line((-125 + 10 * i, 1), (-125 + 10 * i, 1 - (6 if i % 5 == 0 else 3)))
            }
            for j in range(6) {
                n = Text(str(50 * j), position=(-125 + 50 * j, -10), size=3, valign="middle")
            }
        }
    }

    feet_a = foot()
    feet_b = foot()

    # flat on the sheet
    Below(keeper, board, gap=10)
    AlignLeft(keeper, board)
    RightOf(feet_a, board, gap=10)
    AlignTop(feet_a, board)
    Below(feet_b, feet_a, gap=10)
    AlignLeft(feet_b, feet_a)

    # in 3D: the board upright facing the front, its bottom edge on the table; the feet
    # across it at x = -110 and 110; the keeper on the board's face
    Place(board, position=(0, 0, BH / 2), face="front", up="up")
    Place(feet_a, position=(-110 mm - T / 2, -T / 2, FOOT_H / 2), face="right", up="up")
    Place(feet_b, position=(110 mm - T / 2, -T / 2, FOOT_H / 2), face="right", up="up")
    Place(keeper, on=board, position=(0, 30))

    assert board.body.width == 320 mm and board.body.height == 240 mm, "board 320 x 240"
    assert board.slot_r.cut.center.x - board.body.center.x == 110 mm, "feet 110 from the middle"
    assert board.slot_l.depth + feet_a.slot.depth == FOOT_H, "halvings add up to the foot"
    assert feet_a.body.width == 160 mm, "feet 160 long"
    assert keeper.bar.width == 320 mm and keeper.bar.height == 30 mm, "keeper 320 x 30"
    assert keeper.magnets.left.diameter == 10.2 mm, "10.2 mm magnet holes"
    assert keeper.magnets.left.center.x - keeper.bar.bb.left == 12 mm, "magnets 12 in from the ends"
    assert keeper.window.w.width == 260 mm and keeper.window.w.height == 6 mm, "260 x 6 window"
    assert keeper.window.w.center.y - keeper.bar.center.y == 5 mm, "window 5 above the middle"
    assert len(keeper.scale.tick) == 26, "ticks 0 to 250"
    assert keeper.scale.tick[1].start.x - keeper.scale.tick[0].start.x == 10 mm, "every 10 mm"
    assert distance(keeper.magnets, keeper.window) >= 3 mm, "magnets clear of the window"
    assert distance(keeper.scale, keeper.window) >= 0.5 mm, "scale under the window"
    assert board.body.bb.top - board.title.t.position.y == 15 mm, "title 15 below the top"
}
