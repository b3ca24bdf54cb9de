# Request (crafts): a small warping board for a rigid-heddle loom (warps up to about 6 m),
# 9 mm birch ply, hung on the wall. A frame 500 x 350 mm outside of four 60 mm rails: the
# top and bottom rails run the full 500 mm; the two side rails fit between them with two
# 12 mm-deep sliding dovetails (10 deg) at each end. 12 mm dowel pegs are glued into 11.8 mm
# holes: a start peg 60 mm in from the left end of the top rail and three cross pegs 40 mm
# apart to its right starting 70 mm from the start peg; four pegs up each side rail, 60 mm
# apart, centred on the rail; two on the bottom rail 120 mm either side of the middle. Two
# keyholes (8 mm head, 4 mm shank) 150 mm either side of the top rail's middle. The bottom
# rail is engraved filled "HANNAH'S WEAVING" in its middle.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 9 mm

frame_w = 500 mm
frame_h = 350 mm
rail = 60 mm
side_len = frame_h - 2 * rail     # between the top and bottom rails
dt_depth = 12 mm
peg_d = 11.8 mm
side_x = frame_w / 2 - rail / 2   # the side rails' middle, from the frame's middle

def peg(x=0 mm, y=0 mm) -> hole {
    c = Circle(center=(x, y), diameter=peg_d)
}

def side_rail() -> solid {
    body = Rectangle(center=(0, 0), width=rail, height=side_len + 2 * dt_depth)
    top_t = dovetail(part="tail", length=rail, depth=dt_depth, tails=2, angle=10 deg,
                     rotation=0 deg, cx=0 mm, cy=side_len / 2)
    bot_t = dovetail(part="tail", length=rail, depth=dt_depth, tails=2, angle=10 deg,
                     rotation=180 deg, cx=0 mm, cy=-side_len / 2)
    for i in range(4) {
        p = peg(x=0 mm, y=-90 mm + i * 60 mm)
    }
}

assembly warping_board {
    solid top {
        body = Rectangle(center=(0, 0), width=frame_w, height=rail)
        left_s = dovetail(part="socket", length=rail, depth=dt_depth, tails=2, angle=10 deg,
                          rotation=0 deg, cx=-side_x, cy=-rail / 2)
        right_s = dovetail(part="socket", length=rail, depth=dt_depth, tails=2, angle=10 deg,
                           rotation=0 deg, cx=side_x, cy=-rail / 2)
        start = peg(x=-frame_w / 2 + 60 mm, y=0 mm)
        for i in range(3) {
            cross = peg(x=-frame_w / 2 + 60 mm + 70 mm + i * 40 mm, y=0 mm)
        }
        hang_l = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg)
        hang_r = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg)
        hang_l.head_hole.center == (-150, 0)
        hang_r.head_hole.center == (150, 0)
    }

    solid bottom {
        body = Rectangle(center=(0, 0), width=frame_w, height=rail)
        left_s = dovetail(part="socket", length=rail, depth=dt_depth, tails=2, angle=10 deg,
                          rotation=180 deg, cx=-side_x, cy=rail / 2)
        right_s = dovetail(part="socket", length=rail, depth=dt_depth, tails=2, angle=10 deg,
                           rotation=180 deg, cx=side_x, cy=rail / 2)
        pl = peg(x=-120 mm, y=0 mm)
        pr = peg(x=120 mm, y=0 mm)
        drawing name {
            t = Text("HANNAH'S WEAVING", position=(0, 0), size=12, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    left = side_rail()
    right = side_rail()

    # on the sheet
    Below(bottom, top, gap=8)
    AlignLeft(bottom, top)
    Below(left, bottom, gap=8)
    AlignLeft(left, bottom)
    RightOf(right, left, gap=8)
    AlignTop(right, left)

    # in 3D: the frame flat on the wall, drawn face up
    Place(top, position=(0, frame_h / 2 - rail / 2, 0), face="up", up="back")
    Place(bottom, position=(0, -frame_h / 2 + rail / 2, 0), face="up", up="back")
    Place(left, position=(-side_x, 0, 0), face="up", up="back")
    Place(right, position=(side_x, 0, 0), face="up", up="back")

    # the request's numbers
    assert top.body.width == 500 mm and left.body.height - 2 * dt_depth + 2 * rail == 350 mm
    assert len(left.p) == 4 and len(top.cross) == 3
    assert top.start.c.center.x - top.body.bb.left == 60 mm
    assert top.cross[0].c.center.x - top.start.c.center.x == 70 mm
    assert top.cross[1].c.center.x - top.cross[0].c.center.x == 40 mm
    assert left.p[1].c.center.y - left.p[0].c.center.y == 60 mm
    assert bottom.pr.c.center.x - bottom.pl.c.center.x == 240 mm
    assert top.hang_r.head_hole.center.x - top.hang_l.head_hole.center.x == 300 mm
    assert top.start.c.diameter == 11.8 mm
}
