# Request (crafts): a bookbinding punching cradle for sewing signatures, from 6 mm ply. Two
# boards 250 mm long between the end frames and 60 mm wide lie in a 90 degree V, their top
# faces flush with the V edges of the frames, leaving a 3 mm gap along the bottom of the V
# for the awl. Each board end carries two 15 mm glued tenons through mortises in the end
# frames. End frames 160 mm wide, 90 mm tall, the V's bottom 25 mm above the feet. Board A
# has a scale engraved along its gap edge: a tick every 10 mm from the inside face of the
# frame (long ticks every 50 mm, numbered 50 to 200); board B has "PUNCH CRADLE" engraved
# 8 mm tall in its middle.

units mm
thickness 6 mm
kerf 0.15 mm

import "std/joints.aidl"

ply = 6 mm
inner_l = 250 mm
board_w = 60 mm
awl_gap = 3 mm
tenon = 15 mm
frame_w = 160 mm
frame_h = 90 mm
apex_y = 25 mm
r2 = sqrt(2)
s0 = awl_gap / r2                    # board edge from the apex, along the V side
s_mid = s0 + board_w / 2             # board middle along the V side
# mortise middle: s_mid along the V side, half a board under it
mort_x = (s_mid + ply / 2) / r2
mort_y = apex_y + (s_mid - ply / 2) / r2
# board's bottom face middle in 3D (y across, z up), for Place
bot_y = (s_mid + ply) / r2
bot_z = apex_y + (s_mid - ply) / r2

def end_frame() -> solid {
    outline = Polygon([(-frame_w / 2, 0), (frame_w / 2, 0), (frame_w / 2, frame_h),
                       (frame_h - apex_y, frame_h), (0, apex_y),
                       (-(frame_h - apex_y), frame_h), (-frame_w / 2, frame_h)])
    Fixed(outline)
    m_a = tab_and_slot(part="slot", length=board_w, thickness=ply, tabs=2, tab=tenon, screw=0,
                       clearance=0.1 mm, rotation=45 deg, cx=mort_x, cy=mort_y)
    m_b = tab_and_slot(part="slot", length=board_w, thickness=ply, tabs=2, tab=tenon, screw=0,
                       clearance=0.1 mm, rotation=-45 deg, cx=-mort_x, cy=mort_y)
}

def cradle_board() -> solid {
    board = Rectangle(center=(0, 0), width=inner_l + 2 * ply, height=board_w)
    Fixed(board)
    left = tab_and_slot(part="tab", length=board_w, thickness=ply, tabs=2, tab=tenon, screw=0,
                        rotation=90 deg, cx=-inner_l / 2 - ply, cy=0 mm)
    right = tab_and_slot(part="tab", length=board_w, thickness=ply, tabs=2, tab=tenon, screw=0,
                         rotation=-90 deg, cx=inner_l / 2 + ply, cy=0 mm)
}

assembly cradle {
    frame_l = end_frame()
    frame_r = end_frame()
    board_a = cradle_board()
    board_b = cradle_board()

    drawing scale {
        for i in range(1, 25) {
            tick = Line((-inner_l / 2 + i * 10 mm, -board_w / 2 + 1 mm),
                        (-inner_l / 2 + i * 10 mm, -board_w / 2 + (9 mm if i % 5 == 0 else 5 mm)))
        }
        for k in range(1, 5) {
            num = Text(str(k * 50), position=(-inner_l / 2 + k * 50 mm, -board_w / 2 + 12 mm),
                       size=4)
        }
    }
    CutInto(scale, board_a)
    Rigid(scale, board_a)
    drawing label {
        t = Text("PUNCH CRADLE", position=(0, 0), size=8, valign="middle")
    }
    CutInto(label, board_b)
    CenterInside(label, board_b.board)

    # flat on the sheet
    RightOf(frame_r, frame_l, gap=10)
    AlignBottom(frame_r, frame_l)
    Below(board_a, frame_l, gap=10)
    Below(board_b, board_a, gap=10)
    AlignLeft(board_a, frame_l)
    AlignLeft(board_b, frame_l)

    # assembled: x along the cradle, y across, z up
    Place(frame_l, rotation=(90 deg, 0, 90 deg), position=(-inner_l / 2 - ply, 0, 0))
    Place(frame_r, rotation=(90 deg, 0, 90 deg), position=(inner_l / 2, 0, 0))
    Place(board_a, rotation=(45 deg, 0, 0), position=(0, bot_y, bot_z))
    Place(board_b, rotation=(-45 deg, 0, 0), position=(0, -bot_y, bot_z))

    assert board_a.board.width - 2 * ply == 250 mm and board_a.board.height == 60 mm, "boards 250 x 60"
    assert frame_l.outline.bb.width == 160 mm and frame_l.outline.bb.height == 90 mm, "frames 160 x 90"
    assert s0 * r2 == 3 mm, "3 mm awl gap"
    assert (frame_h - apex_y) * r2 >= s0 + board_w, "the board fits on the V side"
    assert len(scale.tick) == 24 and len(scale.num) == 4, "24 ticks, 4 numbers"
}
