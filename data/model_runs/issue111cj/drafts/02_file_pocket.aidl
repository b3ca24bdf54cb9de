# Request: a wall-mounted A4 file pocket for the office, 4 mm birch ply, glued. A back board
# 250 wide x 320 tall hung on two screws by keyhole slots 160 mm apart, their heads' centres
# 30 mm below the top. The pocket is 230 mm wide outside (centred, 10 mm of back showing each
# side) and 40 mm deep inside, made of a front 250 wide x 180 tall, two sides 170 tall and a
# base whose underside is 10 mm above the bottom edges. Sides and base are tabbed through
# mortises in the back and the front. The front has a thumb scoop in its top edge, 80 wide and
# 30 deep (half an ellipse), and "INBOX" engraved filled in 30 mm bold letters, centred.

units mm
thickness 4 mm
import "std/joints.aidl"
import "std/plates.aidl"

t = 4 mm
W = 250 mm          # back and front width
pocket_w = 230 mm   # pocket width outside the sides
depth = 40 mm       # inside depth
side_h = 170 mm
base_z = 10 mm      # underside of the base above the bottom edges
inset = (W - pocket_w) / 2
base_w = pocket_w - 2 * t

# mortises for both sides and the base, the same on the back and the front
def mortises() -> hole {
    left = tab_and_slot(part="slot", length=side_h, thickness=t, tabs=3, tab=20 mm, screw=0,
                        rotation=90 deg, cx=inset + t / 2, cy=side_h / 2)
    right = tab_and_slot(part="slot", length=side_h, thickness=t, tabs=3, tab=20 mm, screw=0,
                         rotation=90 deg, cx=W - inset - t / 2, cy=side_h / 2)
    bottom = tab_and_slot(part="slot", length=base_w, thickness=t, tabs=3, tab=30 mm, screw=0,
                          cx=W / 2, cy=base_z + t / 2)
}

def side() -> solid {
    body = Rectangle(bottom_left=(-t, 0), width=depth + 2 * t, height=side_h)
    to_front = tab_and_slot(part="tab", length=side_h, thickness=t, tabs=3, tab=20 mm, screw=0,
                            rotation=90 deg, cx=-t, cy=side_h / 2)
    to_back = tab_and_slot(part="tab", length=side_h, thickness=t, tabs=3, tab=20 mm, screw=0,
                           rotation=-90 deg, cx=depth + t, cy=side_h / 2)
}

assembly pocket {
    solid back {
        board = Rectangle(bottom_left=(0, 0), width=W, height=320)
        m = mortises()
        hang_l = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg,
                         cx=W / 2 - 80 mm, cy=320 - 30)
        hang_r = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg,
                         cx=W / 2 + 80 mm, cy=320 - 30)
    }
    solid front {
        board = Rectangle(bottom_left=(0, 0), width=W, height=180)
        m = mortises()
        hole scoop {
            e = Ellipse(center=(W / 2, 180), rx=40, ry=30)
        }
        drawing label {
            word = Text("INBOX", position=(W / 2, 85), size=30, font="sans:Bold",
                        valign="middle", fill=true)
        }
    }
    left_side = side()
    right_side = side()
    solid base {
        board = Rectangle(bottom_left=(0, -t), width=base_w, height=depth + 2 * t)
        to_front = tab_and_slot(part="tab", length=base_w, thickness=t, tabs=3, tab=30 mm, screw=0,
                                rotation=180 deg, cx=base_w / 2, cy=-t)
        to_back = tab_and_slot(part="tab", length=base_w, thickness=t, tabs=3, tab=30 mm, screw=0,
                               cx=base_w / 2, cy=depth + t)
    }

    # flat on the sheet: side by side
    RightOf(front, back, gap=10)
    AlignBottom(front, back)
    Above(base, front, gap=10)
    AlignLeft(base, front)
    RightOf(left_side, front, gap=10)
    AlignBottom(left_side, back)
    RightOf(right_side, left_side, gap=10)
    AlignBottom(right_side, back)

    # in 3D: x to the right, z up, the wall behind at +y, the front at y = -4..0
    Place(front, rotation=(90 deg, 0, 0), position=(0, 0, 0))
    Place(back, rotation=(90 deg, 0, 0), position=(0, depth + t, 0))
    Place(left_side, rotation=(90 deg, 0, 90 deg), position=(inset, 0, 0))
    Place(right_side, rotation=(90 deg, 0, 90 deg), position=(W - inset - t, 0, 0))
    Place(base, position=(inset + t, 0, base_z))

    assert back.board.width == 250 mm and back.board.height == 320 mm
    assert front.board.width == 250 mm and front.board.height == 180 mm
    assert back.hang_r.head_hole.center.x - back.hang_l.head_hole.center.x == 160 mm
    assert back.board.bb.top - back.hang_l.head_hole.center.y == 30 mm
    assert front.m.right.slot[0].bb.right - front.m.left.slot[0].bb.left == 230 mm, "pocket 230 wide"
    assert left_side.body.width - 2 * t == 40 mm, "40 mm deep inside"
    assert left_side.body.height == 170 mm
    assert front.scoop.e.rx * 2 == 80 mm and front.scoop.e.ry == 30 mm
    assert front.m.bottom.slot[0].bb.bottom - front.board.bb.bottom == 10 mm
}
