# Office: a monitor riser in 6 mm plywood. Top board 360 x 200 mm, corners R10, with a cable
# slot 80 x 20 mm (rounded ends) centred 30 mm in from the back (top) edge. Two legs 200 mm long
# (the riser's depth) x 80 mm tall overall, glued into the top: each leg's top edge has 3 tabs
# 20 mm wide (tab_and_slot, screw=0, clearance 0.1 mm) going into mortises in the top board whose
# centre lines are 20 mm in from the board's left and right ends.

import "std/joints.aidl"

thickness 6 mm

param t = 6 mm, min = 3 mm, max = 9 mm
param depth = 200 mm, min = 150 mm, max = 250 mm
param leg_h = 80 mm, min = 40 mm, max = 120 mm

def leg() -> solid {
    body = Rectangle(center=(0, 0), width=depth, height=leg_h)
    j = tab_and_slot(part="tab", length=depth, thickness=t, tabs=3, tab=20 mm, screw=0,
                     clearance=0.1 mm, rotation=180 deg, cx=0 mm, cy=leg_h / 2 - t)
}

assembly riser {
    solid top {
        board = RoundedRectangle(center=(0, 0), width=360, height=depth, corner_radius=10)
        hole cable {
            s = Slot(center=(0, depth / 2 - 30), length=80, width=20)
        }
        ml = tab_and_slot(part="slot", length=depth, thickness=t, tabs=3, tab=20 mm, screw=0,
                          clearance=0.1 mm, rotation=90 deg, cx=-160 mm, cy=0 mm)
        mr = tab_and_slot(part="slot", length=depth, thickness=t, tabs=3, tab=20 mm, screw=0,
                          clearance=0.1 mm, rotation=90 deg, cx=160 mm, cy=0 mm)
    }
    left_leg = leg()
    right_leg = leg()
    Below(left_leg, top, gap=10)
    AlignLeft(left_leg, top)
    RightOf(right_leg, left_leg, gap=10)
    AlignCenterY(right_leg, left_leg)

    assert top.board.bb.width == 360 mm and top.board.bb.height == 200 mm, "top 360 x 200"
    assert top.cable.bb.width == 80 mm and top.cable.bb.height == 20 mm, "cable slot 80 x 20"
    assert top.board.bb.top - top.cable.s.center.y == 30 mm, "cable slot 30 in from the back"
    assert left_leg.bb.width == 200 mm and left_leg.bb.height == 80 mm, "leg 200 x 80"
    assert top.ml.bb.center_x - top.board.bb.left == 20 mm, "left mortises 20 in"
    assert top.board.bb.right - top.mr.bb.center_x == 20 mm, "right mortises 20 in"
}
