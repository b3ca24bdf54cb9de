# Kitchen: a chopping-board stand of 3 mm plywood. Two sides 160 mm wide and 115 mm tall:
# straight ends 70 mm tall and an arched top (an arc through the top middle). Each side has
# three 14 mm wide slots with round bottoms for the boards, leaning back 15 deg from vertical,
# the bottoms' centres 55 mm above the base at 40, 80 and 120 mm from the left end. Two rails
# 220 x 30 mm join the sides by cross halving (15 mm into each, 3 mm wide + 0.1 mm
# clearance), 25 mm in from each end of the sides, the sides 180 mm apart on the rails.

import "std/joints.aidl"

thickness 3 mm

param side_w = 160 mm, min = 120 mm, max = 220 mm
param side_h = 115 mm, min = 90 mm, max = 160 mm
param end_h = 70 mm, min = 50 mm, max = 100 mm
param slot_w = 14 mm, min = 8 mm, max = 25 mm
param lean = 15 deg, min = 0 deg, max = 25 deg
param rail_l = 220 mm, min = 150 mm, max = 300 mm
param rail_h = 30 mm, min = 20 mm, max = 50 mm
param spread = 180 mm, min = 100 mm, max = 260 mm

slot_x = [40 mm, 80 mm, 120 mm]
slot_floor = 55 mm
rail_x = [25 mm, side_w - 25 mm]

def side() -> solid {
    base = Line((0, 0), (side_w, 0))
    right_end = Line((side_w, 0), (side_w, end_h))
    top = Arc(start=(side_w, end_h), through=(side_w / 2, side_h), end=(0, end_h))
    left_end = Line((0, end_h), (0, 0))
    hole boards {
        for x in slot_x {
            s = Slot(start=(x, slot_floor), length=80 mm, angle=90 deg + lean, width=slot_w)
        }
    }
    for x in rail_x {
        j = cross_halving(depth=rail_h / 2, thickness=3 mm, clearance=0.1 mm,
                          rotation=180 deg, cx=x, cy=0 mm)
    }
}

def rail() -> solid {
    bar = Rectangle(center=(0, 0), width=rail_l, height=rail_h)
    for x in [-spread / 2, spread / 2] {
        j = cross_halving(depth=rail_h / 2, thickness=3 mm, clearance=0.1 mm,
                          cx=x, cy=rail_h / 2)
    }
}

assembly board_stand {
    left_side = side()
    right_side = side()
    front_rail = rail()
    back_rail = rail()
    RightOf(right_side, left_side, gap=10 mm)
    Below(front_rail, left_side, gap=10 mm)
    AlignLeft(front_rail, left_side)
    Below(back_rail, front_rail, gap=10 mm)
    AlignLeft(back_rail, front_rail)

    # the side's own box counts the slots run past the arch: measure its outline
    assert left_side.base.length == 160 mm, "sides 160 mm wide"
    assert left_side.top.bb.top - left_side.base.start.y == 115 mm, "sides 115 mm tall"
    assert left_side.right_end.length == 70 mm, "straight ends 70 mm"
    assert len(left_side.boards.s) == 3, "three board slots"
    assert left_side.boards.s[0].width == 14 mm, "14 mm slots"
    assert left_side.boards.s[1].start.y - left_side.base.start.y == 55 mm, "slot bottoms 55 mm up"
    assert front_rail.bar.bb.width == 220 mm and front_rail.bar.bb.height == 30 mm, "rails 220 x 30"
    assert front_rail.j[1].cut.bb.height == 15 mm, "halving 15 mm into the rail"
    assert left_side.j[0].cut.bb.height == 15 mm, "halving 15 mm into the side"
}
