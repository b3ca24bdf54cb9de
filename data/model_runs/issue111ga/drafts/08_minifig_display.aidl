# Request: a wall display for a child's Lego minifigures, a birthday present, 3 mm ply,
# glued. Four shelves of six figures: the frame is 174 mm wide inside, with five boards
# (four shelves and a top) 17 mm deep and 48 mm clear between them, held by tabs in two
# sides and a 192 x 262 back. Each board has two 30 mm tabs into the back and an 8 mm tab
# at each end into the sides; each side has three 20 mm tabs into the back; 0.1 mm
# clearance in every slot. Each shelf has six engraved 16 x 8 mm outlines, 29 mm apart, where
# a 1 x 2 Lego plate is glued for a figure to stand on. Over the frame the back carries
# "JAMIE'S MINIFIGS" in 10 mm bold filled letters and two keyholes 160 mm apart to hang it.

import "std/joints.aidl"
import "std/plates.aidl"

t = 3 mm
thickness t

inner_w = 174 mm
depth = 17 mm          # in front of the back
clear_h = 48 mm
pitch = clear_h + t    # board to board
boards = 5
figs = 6
fig_pitch = 29 mm
clr = 0.1 mm

back_w = 192 mm
back_h = 262 mm
side_lo = 3 mm                               # the sides' bottom, over the back's bottom
def board_y(k) = side_lo + 4.5 mm + k * pitch   # the middle of board k in the back's frame
side_hi = board_y(boards - 1) + 1.5 mm + 3 mm
side_h = side_hi - side_lo
side_x = inner_w / 2 + t / 2                 # the sides' middle planes

def board(spots=true) -> solid {
    body = Rectangle(corner=(-inner_w / 2 - t, -depth - t), opposite=(inner_w / 2 + t, 0))
    back_j = tab_and_slot(part="tab", length=inner_w + 2 * t, thickness=t, tabs=2, tab=30 mm,
                          screw=0, cx=0 mm, cy=0 mm)
    end_l = tab_and_slot(part="tab", length=depth + t, thickness=t, tabs=1, tab=8 mm, screw=0,
                         rotation=90 deg, cx=-inner_w / 2 - t, cy=-(depth + t) / 2)
    end_r = tab_and_slot(part="tab", length=depth + t, thickness=t, tabs=1, tab=8 mm, screw=0,
                         rotation=-90 deg, cx=inner_w / 2 + t, cy=-(depth + t) / 2)
    if spots {
        drawing plates {
            for i in range(figs) {
                r = Rectangle(center=(-(figs - 1) / 2 * fig_pitch + i * fig_pitch, -t - depth / 2),
                              width=16, height=8)
            }
        }
    }
}

def side() -> solid {
    body = Rectangle(corner=(-depth - t, side_lo), opposite=(0, side_hi))
    back_j = tab_and_slot(part="tab", length=side_h, thickness=t, tabs=3, tab=20 mm, screw=0,
                          rotation=-90 deg, cx=0 mm, cy=(side_lo + side_hi) / 2)
    for k in range(boards) {
        m = tab_and_slot(part="slot", length=depth + t, thickness=t, tabs=1, tab=8 mm, screw=0,
                         clearance=clr, cx=-(depth + t) / 2, cy=board_y(k))
    }
}

assembly display {
    solid back {
        body = Rectangle(corner=(-back_w / 2, 0), opposite=(back_w / 2, back_h))
        for k in range(boards) {
            bs = tab_and_slot(part="slot", length=inner_w + 2 * t, thickness=t, tabs=2,
                              tab=30 mm, screw=0, clearance=clr, cx=0 mm, cy=board_y(k))
        }
        ss_l = tab_and_slot(part="slot", length=side_h, thickness=t, tabs=3, tab=20 mm, screw=0,
                            clearance=clr, rotation=90 deg, cx=-side_x, cy=(side_lo + side_hi) / 2)
        ss_r = tab_and_slot(part="slot", length=side_h, thickness=t, tabs=3, tab=20 mm, screw=0,
                            clearance=clr, rotation=90 deg, cx=side_x, cy=(side_lo + side_hi) / 2)
        hang_l = keyhole(head=8 mm, slot_width=4 mm, length=8 mm, cx=-80 mm, cy=back_h - 16 mm)
        hang_r = keyhole(head=8 mm, slot_width=4 mm, length=8 mm, cx=80 mm, cy=back_h - 16 mm)
        drawing name {
            w = Text("JAMIE'S MINIFIGS", position=(0, (side_hi + back_h) / 2), size=10,
                     font="sans:Bold", valign="middle", fill=true)
        }
        Fixed(body)
    }

    for k in range(boards) {
        b = board(spots=(k < boards - 1))
    }
    left = side()
    right = side()

    # flat on the sheet: the back, the boards in a column beside it, the sides beyond
    for k in range(boards) {
        RightOf(b[k], back, gap=4)
        if k == 0 {
            AlignTop(b[k], back)
        } else {
            Below(b[k], b[k - 1], gap=4)
        }
    }
    RightOf(left, b[0], gap=4)
    AlignTop(left, back)
    RightOf(right, left, gap=4)
    AlignTop(right, back)

    # assembled: the back upright, its front face on y 0; boards level, sides upright
    Place(back, position=(0, t, 0), face="front", up="up")
    for k in range(boards) {
        Place(b[k], position=(0, t, board_y(k) - t / 2), face="up")
    }
    Place(left, position=(-side_x - t / 2, t, 0), face="right", up="up")
    Place(right, position=(side_x - t / 2, t, 0), face="right", up="up")

    # the request's numbers
    assert len(b) == 5, "four shelves and a top"
    assert len(b[0].plates.r) == 6, "six figures a shelf"
    assert b[0].plates.r[1].center.x - b[0].plates.r[0].center.x == 29 mm, "29 mm apart"
    assert b[0].plates.r[0].width == 16 mm and b[0].plates.r[0].height == 8 mm, "16 x 8 outlines"
    assert b[0].body.bb.width - 2 * t == 174 mm, "174 mm inside"
    assert b[0].body.bb.height - t == 17 mm, "17 mm deep"
    assert board_y(1) - board_y(0) - t == 48 mm, "48 mm clear between boards"
    assert back.body.bb.width == 192 mm and back.body.bb.height == 262 mm, "a 192 x 262 back"
    assert back.hang_r.head_hole.center.x - back.hang_l.head_hole.center.x == 160 mm,
        "keyholes 160 mm apart"
    assert back.name.bb.bottom >= side_hi + 3 mm, "the name over the frame"
    assert distance(back.name, back.hang_l) >= 3 mm and distance(back.name, back.hang_r) >= 3 mm,
        "the name clears the keyholes"
    assert left.m[4].slot[0].bb.top <= left.body.bb.top - 1 mm, "the top mortise closed"
    assert left.m[0].slot[0].bb.bottom >= left.body.bb.bottom + 1 mm, "the bottom mortise closed"
}
