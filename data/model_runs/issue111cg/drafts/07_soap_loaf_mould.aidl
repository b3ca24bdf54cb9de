# Request (crafts): a knock-down loaf mould for 1 kg of cold-process soap, cut from 6 mm ply,
# the space inside 250 long, 80 wide and 80 deep (lined with baking paper). A 300 x 116 mm
# base; two long sides 280 mm long standing on it by three 30 mm tabs each; two ends set
# between the sides, each held by two 20 mm tabs through mortises in both sides (9 mm of side
# left beyond each mortise) and one 30 mm tab into the base. Nothing glued: it pulls apart to
# free the loaf. On the front side's outer face, cutting marks for ten 25 mm bars: nine
# engraved ticks 10 mm long from the top edge down, and the numbers 1 to 10 engraved 5 mm
# tall in the middle of each bar, under the ticks.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
IN_L = 250 mm
IN_W = 80 mm
IN_H = 80 mm
SIDE_L = 280 mm
END_X = IN_L / 2 + T / 2         # each end's middle from the centre
SIDE_Y = IN_W / 2 + T / 2        # each side's middle from the centre
BAR = 25 mm

def side(marks=false) -> solid {
    body = Rectangle(bottom_left=(-SIDE_L / 2, 0), width=SIDE_L, height=IN_H + T)
    feet = tab_and_slot(part="tab", length=SIDE_L, thickness=T, tabs=3, tab=30 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    seat_l = tab_and_slot(part="slot", length=IN_H, thickness=T, tabs=2, tab=20 mm, screw=0,
                          rotation=90 deg, cx=-END_X, cy=T + IN_H / 2)
    seat_r = tab_and_slot(part="slot", length=IN_H, thickness=T, tabs=2, tab=20 mm, screw=0,
                          rotation=90 deg, cx=END_X, cy=T + IN_H / 2)
    if marks {
        drawing scale {
            for k in range(1, 10) {
                tick = Line((-IN_L / 2 + k * BAR, T + IN_H - 1 mm),
                            (-IN_L / 2 + k * BAR, T + IN_H - 11 mm))
            }
            for k in range(10) {
                n = Text(str(k + 1), position=(-IN_L / 2 + (k + 0.5) * BAR, T + IN_H - 18 mm),
                         size=5, valign="middle")
            }
        }
    }
}

def end() -> solid {
    body = Rectangle(bottom_left=(-IN_W / 2 - T, 0), width=IN_W + 2 * T, height=IN_H + T)
    foot = tab_and_slot(part="tab", length=IN_W + 2 * T, thickness=T, tabs=1, tab=30 mm,
                        screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
    lock_l = tab_and_slot(part="tab", length=IN_H, thickness=T, tabs=2, tab=20 mm, screw=0,
                          rotation=90 deg, cx=-IN_W / 2 - T, cy=T + IN_H / 2)
    lock_r = tab_and_slot(part="tab", length=IN_H, thickness=T, tabs=2, tab=20 mm, screw=0,
                          rotation=-90 deg, cx=IN_W / 2 + T, cy=T + IN_H / 2)
}

assembly soap_loaf_mould {
    solid base {
        board = Rectangle(center=(0, 0), width=300, height=116)
        front_seat = tab_and_slot(part="slot", length=SIDE_L, thickness=T, tabs=3, tab=30 mm,
                                  screw=0, cx=0 mm, cy=-SIDE_Y)
        back_seat = tab_and_slot(part="slot", length=SIDE_L, thickness=T, tabs=3, tab=30 mm,
                                 screw=0, cx=0 mm, cy=SIDE_Y)
        left_seat = tab_and_slot(part="slot", length=IN_W + 2 * T, thickness=T, tabs=1,
                                 tab=30 mm, screw=0, rotation=90 deg, cx=-END_X, cy=0 mm)
        right_seat = tab_and_slot(part="slot", length=IN_W + 2 * T, thickness=T, tabs=1,
                                  tab=30 mm, screw=0, rotation=90 deg, cx=END_X, cy=0 mm)
    }
    front = side(marks=true)
    back = side()
    left = end()
    right = end()

    # on the sheet
    Below(front, base, gap=10)
    AlignLeft(front, base)
    Below(back, front, gap=10)
    AlignLeft(back, front)
    RightOf(left, base, gap=10)
    AlignTop(left, base)
    Below(right, left, gap=10)
    AlignLeft(right, left)

    # in 3D: sides' x -> x, y -> z, thickness -> -y; ends' x -> y, y -> z, thickness -> x
    Place(front, position=(0, -SIDE_Y + T / 2, 0), rotation=(90 deg, 0, 0))
    Place(back, position=(0, SIDE_Y + T / 2, 0), rotation=(90 deg, 0, 0))
    Place(left, position=(-END_X - T / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(right, position=(END_X - T / 2, 0, 0), rotation=(90 deg, 0, 90 deg))

    # the request's numbers
    assert base.board.width == 300 mm and base.board.height == 116 mm, "base 300 x 116"
    assert front.seat_r.slot[0].bb.left - front.seat_l.slot[0].bb.right == 250 mm, "250 inside"
    assert base.back_seat.slot[0].bb.bottom - base.front_seat.slot[0].bb.top == 80 mm,
        "80 wide inside"
    assert front.body.height - T == 80 mm, "80 deep inside"
    assert front.body.width == 280 mm, "sides 280 long"
    assert front.body.bb.right - front.seat_r.slot[0].bb.right == 9 mm, "9 mm beyond mortise"
    assert len(front.scale.tick) == 9 and len(front.scale.n) == 10, "9 ticks, 10 bars"
    assert front.scale.tick[0].start.x - front.seat_l.slot[0].bb.right == 25 mm, "25 mm bars"
}
