# Office: a document copy holder that stands beside my keyboard, 3 mm plywood.
# Back board 250 wide x 300 tall, top corners rounded R10, a 90 x 22 mm hand
# hole centred 30 mm below the top edge. A ledge 250 x 30 mm glued into the
# front of the board with 2 tabs 40 mm wide, the ledge's middle 25 mm above the
# board's bottom edge. Two triangular legs glued into the back of the board with
# 3 tabs 20 mm wide along their 200 mm board edge, 25 mm in from each side edge,
# so the board leans back at 70 degrees from the desk (the leg's desk edge is
# 70 deg from its board edge, its back edge square to the desk). Engraved reading
# ticks on the left margin every 10 mm (26 ticks, 40 mm above the bottom edge to
# the first), every 5th long (8 mm, others 4 mm) and numbered 0-5.

import "std/joints.aidl"

units mm
thickness 3 mm

param t = 3 mm, min = 2, max = 6
param board_w = 250 mm, min = 180, max = 320
param board_h = 300 mm, min = 240, max = 400
param ledge_d = 30 mm, min = 20, max = 50
param along = 200 mm, min = 120, max = 240
param lean = 70 deg, min = 60 deg, max = 80 deg
param leg_inset = 25 mm, min = 20, max = 40

# a leg: its board edge on x = 0 from (0, 0) up to (0, along), the desk edge
# from (0, 0) at lean from the board edge, the back edge square to the desk edge
foot = along * cos(lean)

def leg(along=200 mm, lean=70 deg) -> solid {
    body = Polygon([(0, 0), (0, along),
                    (along * cos(lean) * cos(90 deg - lean), along * cos(lean) * sin(90 deg - lean))])
    j = tab_and_slot(part="tab", length=along, thickness=t, tabs=3, tab=20 mm, screw=0,
                     rotation=90 deg, cx=0 mm, cy=along / 2)
}

assembly copy_holder {
    solid back {
        board = RoundedRectangle(center=(0, 0), width=board_w, height=board_h,
                                 corner_radii=[10, 10, 0, 0])
        hole hand {
            s = Slot(center=(0, board_h / 2 - 30), length=90, width=22)
        }
        AlignCenterX(hand, board)
        hand.s.center.y == board.bb.top - 30 mm

        ledge_slots = tab_and_slot(part="slot", length=board_w, thickness=t, tabs=2, tab=40 mm,
                                   screw=0, cx=0 mm, cy=-board_h / 2 + 25 mm)
        left_slots = tab_and_slot(part="slot", length=along, thickness=t, tabs=3, tab=20 mm,
                                  screw=0, rotation=90 deg, cx=-board_w / 2 + leg_inset,
                                  cy=-board_h / 2 + along / 2)
        right_slots = tab_and_slot(part="slot", length=along, thickness=t, tabs=3, tab=20 mm,
                                   screw=0, rotation=90 deg, cx=board_w / 2 - leg_inset,
                                   cy=-board_h / 2 + along / 2)

        drawing ticks {
            for i in range(26) {
                tick = Line(start=(-board_w / 2 + 4, -board_h / 2 + 40 + i * 10),
                            length=(8 if i % 5 == 0 else 4), angle=0)
            }
            for k in range(6) {
                num = Text(str(k), position=(-board_w / 2 + 15, -board_h / 2 + 40 + k * 50),
                           size=3, anchor="start", valign="middle")
            }
        }

        assert board.bb.width == 250 mm, "board 250 wide"
        assert board.bb.height == 300 mm, "board 300 tall"
        assert len(ticks.tick) == 26, "26 ticks"
        assert ticks.tick[0].start.y - board.bb.bottom == 40 mm, "first tick 40 above the bottom"
        assert ticks.tick[1].start.y - ticks.tick[0].start.y == 10 mm, "ticks every 10"
    }

    solid ledge {
        shelf = Rectangle(center=(0, 0), width=board_w, height=ledge_d)
        j = tab_and_slot(part="tab", length=board_w, thickness=t, tabs=2, tab=40 mm, screw=0,
                         cx=0 mm, cy=ledge_d / 2)
        assert shelf.bb.width == 250 mm, "ledge 250 long"
        assert shelf.bb.height == 30 mm, "ledge 30 deep"
    }

    left_leg = leg(along=along, lean=lean)
    right_leg = leg(along=along, lean=lean)

    Below(ledge, back, gap=10)
    AlignCenterX(ledge, back)
    RightOf(left_leg, back, gap=10)
    AlignBottom(left_leg, back)
    RightOf(right_leg, left_leg, gap=10)
    AlignBottom(right_leg, back)

    assert left_leg.body.points[1].y - left_leg.body.points[0].y == 200 mm, "board edge 200"
    assert abs(foot - 200 mm * cos(70 deg)) < 0.01 mm, "desk edge for a 70 deg lean"
}
