# Request: a classical guitarist's footstool, 6 mm birch ply, glued. The top board is 270 x
# 130 mm (corners R10) and slopes up towards the back: its top surface 130 mm above the floor
# at the front and 150 mm at the back, over 120 mm of depth. Two identical side frames carry
# it, 200 mm apart (inner faces): 140 mm along the floor, the front edge leaning in 10 mm, the
# back edge 10 mm; a 3 mm relief under the middle leaving two 20 mm feet; a 50 x 22 mm
# carrying slot centred 70 mm from the front, 80 mm up; the top edge ends in two 20 mm tabs
# through slots in the board (0.1 mm clearance), flush with its top. A 40 mm tall stretcher,
# sticking out 10 mm past each side, crosses the sides 70 mm from the front in cross-halving
# joints (half from each, 0.1 mm clearance). "M. TORRES" engraved filled in 10 mm bold
# letters on the board, centred 45 mm behind its front edge... (read: 20 mm in from the
# front edge). Lay the parts out for cutting and place them in 3D.

import "std/joints.aidl"

thickness 6 mm

param ply = 6 mm
param between = 200 mm
param foot_len = 140 mm
param front_h = 130 mm
param back_h = 150 mm
param lean = 10 mm
param relief = 3 mm
param stretch_h = 40 mm
param gap = 5 mm

slope = atan2(back_h - front_h, foot_len - 2 * lean)
edge_len = sqrt((back_h - front_h) ** 2 + (foot_len - 2 * lean) ** 2)
mid_x = foot_len / 2
mid_y = (front_h + back_h) / 2

def side() -> solid {
    p = Polygon([(0, 0), (20, 0), (20, relief), (foot_len - 20, relief), (foot_len - 20, 0),
                 (foot_len, 0), (foot_len - lean, back_h), (lean, front_h)])
    top_tabs = tab_and_slot(part="tab", length=edge_len, thickness=ply, tabs=2, tab=20 mm,
                            screw=0, rotation=slope, cx=mid_x, cy=mid_y)
    halving = cross_halving(depth=stretch_h / 2, thickness=ply, clearance=0.1 mm,
                            rotation=180 deg, cx=70 mm, cy=relief)
    hole carry {
        s = Slot(center=(70, 80), length=50, width=22)
    }
}

def top_board() -> solid {
    board = RoundedRectangle(center=(0, 0), width=270, height=130, corner_radius=10)
    left_slots = tab_and_slot(part="slot", length=edge_len, thickness=ply, tabs=2, tab=20 mm,
                              screw=0, clearance=0.1 mm, rotation=90 deg,
                              cx=-(between / 2 + ply / 2), cy=0 mm)
    right_slots = tab_and_slot(part="slot", length=edge_len, thickness=ply, tabs=2, tab=20 mm,
                               screw=0, clearance=0.1 mm, rotation=90 deg,
                               cx=between / 2 + ply / 2, cy=0 mm)
    drawing name {
        t = Text("M. TORRES", position=(0, -45), size=10, font="sans:Bold", valign="middle",
                 fill=true)
    }
}

def stretcher() -> solid {
    w = between + 2 * ply + 20 mm
    bar = Rectangle(bottom_left=(-w / 2, 0), width=w, height=stretch_h)
    left_halving = cross_halving(depth=stretch_h / 2, thickness=ply, clearance=0.1 mm,
                                 cx=-(between / 2 + ply / 2), cy=stretch_h)
    right_halving = cross_halving(depth=stretch_h / 2, thickness=ply, clearance=0.1 mm,
                                  cx=between / 2 + ply / 2, cy=stretch_h)
}

assembly footstool {
    side_a = side()
    side_b = side()
    top = top_board()
    bar = stretcher()

    RightOf(side_b, side_a, gap=gap)
    AlignBottom(side_b, side_a)
    Above(top, side_a, gap=gap)
    AlignLeft(top, side_a)
    Above(bar, top, gap=gap)
    AlignLeft(bar, top)

    # 3D: x across, y from front to back, z up; both sides turned the same way
    Place(side_a, position=(-between / 2 - ply, 0, 0), face="right", up="up")
    Place(side_b, position=(between / 2, 0, 0), face="right", up="up")
    Place(bar, position=(0, 70 mm + ply / 2, relief), face="front", up="up")
    Place(top, position=(0, mid_x + ply * sin(slope), mid_y - ply * cos(slope)),
          rotation=(slope, 0, 0))

    # the request's numbers
    assert top.board.width == 270 mm and top.board.height == 130 mm, "board 270 x 130"
    assert side_a.p.points[7].y == 130 mm, "130 mm high at the front"
    assert side_a.p.points[6].y == 150 mm, "150 mm high at the back"
    assert side_a.p.points[6].x - side_a.p.points[7].x == 120 mm, "over 120 mm of depth"
    assert side_a.p.bb.width == 140 mm, "140 along the floor"
    assert side_a.p.points[2].y == 3 mm and side_a.p.points[1].x == 20 mm, "3 mm relief, 20 mm feet"
    assert side_a.carry.s.length == 50 mm and side_a.carry.s.width == 22 mm, "50 x 22 carrying slot"
    assert side_a.carry.s.center.x == 70 mm and side_a.carry.s.center.y == 80 mm, "slot 70 in, 80 up"
    assert top.right_slots.slot[0].bb.center_x - top.left_slots.slot[0].bb.center_x == 200 mm + ply,
           "sides 200 apart between inner faces"
    assert len(top.left_slots.slot) == 2, "two tabs per side"
    assert bar.bar.width - (between + 2 * ply) == 20 mm, "stretcher sticks out 10 each side"
    assert bar.bar.height == 40 mm, "stretcher 40 tall"
    assert side_a.halving.cut.bb.height + bar.left_halving.cut.bb.height == 40 mm,
           "halvings add up to the stretcher's height"
    assert side_a.halving.cut.bb.center_x == 70 mm, "stretcher 70 mm from the front"
    assert top.board.bb.top - top.name.t.position.y > 0 mm, "name on the board"
    assert distance(top.name, top.left_slots) >= 5 mm, "name clear of the slots"
}
