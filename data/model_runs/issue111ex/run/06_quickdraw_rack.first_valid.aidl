# Request: a wall rack for my climbing quickdraws and slings, 6 mm birch ply, glued. A back
# board 400 x 120 mm (corners R8) hangs on two screws by keyholes (8 mm head, 4 mm slot
# 10 mm long, upward) 30 mm in from the sides and 25 mm below the top. Six hooks, 60 mm
# apart, centred on the board: each a side-profile plate glued into the board by two 10 mm
# tenons (0.1 mm clearance in the mortises) along a 40 mm tall back, the mortises' middle
# 15 mm below the board's centre. From the top of the back a 12 mm wide arm runs 50 mm out
# from the board's face and turns up on a 10 mm radius to a rounded tip 20 mm above the
# arm's centre line, so a carabiner can't slide off. "QUICKDRAWS" engraved filled (14 mm,
# bold serif) centred 25 mm below the top; each hook's number (6 mm) engraved above its
# mortises. Lay the parts out for cutting and place them in 3D.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

param ply = 6 mm
param board_w = 400 mm
param board_h = 120 mm
param hooks = 6
param pitch = 60 mm
param back_h = 40 mm
param arm_w = 12 mm
param reach = 50 mm
param gap = 5 mm

mortise_y = -15 mm

def hook() -> solid {
    # x: out from the board's face (0); y: up, 0 at the arm's centre line
    back = Rectangle(bottom_left=(-ply, arm_w / 2 - back_h), width=ply + 8 mm, height=back_h)
    run = Line((8, 0), (reach, 0))
    bend = Arc(center=(reach, 10), radius=10, start_angle=-90 deg, end_angle=0 deg)
    rise = Line((reach + 10, 10), (reach + 10, 20))
    arm = Stroke([run, bend, rise], width=arm_w)
    tenons = tab_and_slot(part="tab", length=back_h, thickness=ply, tabs=2, tab=10 mm,
                          screw=0, rotation=90 deg, cx=-ply, cy=arm_w / 2 - back_h / 2)
}

solid_names = [str(i + 1) for i in range(hooks)]

assembly quickdraw_rack {
    solid board {
        plate = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=8)
        hang_l = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                         cx=-board_w / 2 + 30 mm, cy=board_h / 2 - 25 mm)
        hang_r = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                         cx=board_w / 2 - 30 mm, cy=board_h / 2 - 25 mm)
        for i in range(hooks) {
            mortise = tab_and_slot(part="slot", length=back_h, thickness=ply, tabs=2, tab=10 mm,
                                   screw=0, clearance=0.1 mm, rotation=90 deg,
                                   cx=(i - (hooks - 1) / 2) * pitch, cy=mortise_y)
        }
        drawing words {
            title = Text("QUICKDRAWS", position=(0, board_h / 2 - 25 mm), size=14,
                         font="serif:Bold", valign="middle", fill=true)
            for i in range(hooks) {
                n = Text(solid_names[i], position=((i - (hooks - 1) / 2) * pitch,
                         mortise_y + back_h / 2 + 5 mm), size=6)
            }
        }
        Fixed(plate)
    }
    for i in range(hooks) {
        h = hook()
    }
    Below(h[0], board, gap=gap)
    AlignLeft(h[0], board)
    for i in range(1, hooks) {
        RightOf(h[i], h[i - 1], gap=gap)
        AlignTop(h[i], h[i - 1])
    }

    # 3D: the wall is y = 0, the board's face looks to the front (-y); z up
    Place(board, position=(0, 0, 0), face="front", up="up")
    for i in range(hooks) {
        # the hook's plate stands upright, its x out from the board's face (-y)
        Place(h[i], position=((i - (hooks - 1) / 2) * pitch + ply / 2, -ply,
                              mortise_y - (arm_w / 2 - back_h / 2)), face="left", up="up")
    }

    # the request's numbers
    assert board.plate.width == 400 mm and board.plate.height == 120 mm, "board 400 x 120"
    assert len(h) == 6 and len(board.mortise) == 6, "six hooks"
    assert board.mortise[1].slot[0].bb.center_x - board.mortise[0].slot[0].bb.center_x == 60 mm,
           "hooks 60 apart"
    assert board.mortise[0].slot[0].bb.center_x + board.mortise[5].slot[0].bb.center_x == 0 mm,
           "hooks centred"
    assert board.hang_l.head_hole.center.x - board.plate.bb.left == 30 mm, "keyholes 30 in"
    assert board.plate.bb.top - board.hang_l.head_hole.center.y == 25 mm, "keyholes 25 down"
    assert board.mortise[0].bb.center_y - board.plate.center.y == -15 mm, "mortises 15 below centre"
    assert h[0].back.height == 40 mm, "40 mm back"
    assert h[0].rise.end.y - h[0].run.start.y == 20 mm, "tip 20 above the arm"
    assert h[0].bend.radius == 10 mm, "10 mm bend"
    assert h[0].bend.center.x == 50 mm, "arm 50 out before the bend"
    assert board.plate.bb.top - board.words.title.position.y == 25 mm, "title 25 below the top"
    assert distance(board.words.title, board.hang_l) >= 3 mm, "title clear of the keyholes"
    assert distance(board.words.n[0], board.mortise[0]) >= 1 mm, "numbers clear of the mortises"
}
