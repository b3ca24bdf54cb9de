# Request: a garden kneeler that flips over into a low seat, cut from 9 mm exterior ply.
# A kneeling board 500 x 260 mm (corners r15, measured over its tabs) stands 200 mm off the
# ground between two end frames. Each end frame is 260 mm deep and 420 mm tall: below the
# board its feet are split by a half-ellipse arch 170 mm wide and 70 mm high; above the board
# it rises into a handle with rounded top corners (r40) and a 110 x 32 mm hand slot whose
# centre is 50 mm below the top. The board passes through each frame on three 40 mm tabs; a
# 60 mm stretcher, centred 120 mm off the ground, braces the frames with one 30 mm tab each
# end. Slots get 0.2 mm clearance. "GROW" engraved filled in a serif face on each handle
# between the board and the hand slot.

import "std/joints.aidl"

thickness 9 mm

param board_l = 500 mm, min = 400, max = 600
param depth = 260 mm, min = 220, max = 320
param seat_h = 200 mm, min = 150, max = 260
param frame_h = 420 mm, min = 350, max = 500

t = 9 mm

def frame() -> solid {
    body = Rectangle(bottom_left=(-depth / 2, 0), width=depth, height=frame_h)
    Fillet([body.top_left, body.top_right], 40 mm)
    hole arch {
        e = Ellipse(center=(0, 0), rx=85, ry=70)
    }
    hole grip {
        s = Slot(center=(0, frame_h - 50), length=110, width=32)
    }
    board_slots = tab_and_slot(part="slot", length=depth, thickness=t, tabs=3, tab=40 mm,
                               screw=0, clearance=0.2 mm, rotation=0 deg, cx=0,
                               cy=seat_h - t / 2)
    rail_slot = tab_and_slot(part="slot", length=60 mm, thickness=t, tabs=1, tab=30 mm,
                             screw=0, clearance=0.2 mm, rotation=90 deg, cx=0, cy=120)
    drawing motto {
        w = Text("GROW", position=(0, (seat_h + frame_h - 50 - 16) / 2), size=24,
                 font="serif:Bold", valign="middle", fill=true)
    }
}

assembly kneeler {
    solid board {
        top = RoundedRectangle(center=(0, 0), width=board_l, height=depth, corner_radius=15)
        left = tab_and_slot(part="tab", length=depth, thickness=t, tabs=3, tab=40 mm, screw=0,
                            rotation=90 deg, cx=-board_l / 2, cy=0)
        right = tab_and_slot(part="tab", length=depth, thickness=t, tabs=3, tab=40 mm, screw=0,
                             rotation=-90 deg, cx=board_l / 2, cy=0)
    }
    solid stretcher {
        bar = Rectangle(center=(0, 0), width=board_l, height=60)
        left = tab_and_slot(part="tab", length=60 mm, thickness=t, tabs=1, tab=30 mm, screw=0,
                            rotation=90 deg, cx=-board_l / 2, cy=0)
        right = tab_and_slot(part="tab", length=60 mm, thickness=t, tabs=1, tab=30 mm, screw=0,
                             rotation=-90 deg, cx=board_l / 2, cy=0)
    }
    for i in range(2) {
        ends = frame()
        # stood up: frame x -> world y (depth), frame y -> world z, thickness -> world x
        Place(ends, rotation=(90 deg, 0, 90 deg),
              position=(-board_l / 2 + i * (board_l - t), 0, 0))
    }
    Place(board, position=(0, 0, seat_h - t))
    # upright along the length: its y -> world z, thickness -> world -y
    Place(stretcher, rotation=(90 deg, 0, 0), position=(0, t / 2, 120))

    # on the sheet
    Below(stretcher, board, gap=10)
    AlignLeft(stretcher, board)
    RightOf(ends[0], board, gap=10)
    AlignTop(ends[0].body, board)
    RightOf(ends[1], ends[0], gap=10)
    AlignBottom(ends[1].body, ends[0].body)

    assert len(ends) == 2, "two end frames"
    assert board.top.bb.width == 500 mm and board.top.bb.height == 260 mm, "board 500 x 260"
    assert ends[0].body.bb.height == 420 mm and ends[0].body.bb.width == 260 mm, "frames 260 x 420"
    assert ends[0].board_slots.bb.center_y - ends[0].body.bb.bottom + t / 2 == 200 mm, "board 200 off the ground"
    assert ends[0].arch.e.rx * 2 == 170 mm and ends[0].arch.e.ry == 70 mm, "arch 170 x 70"
    assert ends[0].body.bb.top - ends[0].grip.s.center.y == 50 mm, "hand slot 50 below the top"
    assert ends[0].rail_slot.bb.center_y - ends[0].body.bb.bottom == 120 mm, "stretcher 120 up"
}
