# Request: a wall-mounted bottle opener with a cap catcher, 6 mm oak ply.
# Back board 180 wide x 300 tall, top corners rounded R20; hangs on two screws through
# keyholes (8 mm head, 4 mm slot) 120 mm apart, 20 mm below the top edge. A cast opener is
# bolted on with two M4 bolts 48 mm apart (vertical), centred 70 mm below the top edge.
# "CHEERS" engraved filled in bold serif, 22 mm tall, centred 10 mm above the board's middle.
# Under it an open-top cap tray 150 wide x 70 deep x 90 tall (outside): a bottom 162 x 76
# (overhangs the walls by 6 mm) glued into the board with 2 tabs 30 mm wide; front and two
# sides finger-jointed at the corners (12 mm fingers) and tabbed into the bottom (front: 2 tabs
# 20 mm, sides: 2 tabs 15 mm); the tray's bottom face 10 mm above the board's bottom edge.

import "std/joints.aidl"
import "std/plates.aidl"
import "std/fasteners.aidl"

units mm
thickness 6 mm

t = 6 mm
tray_w = 150 mm
tray_d = 70 mm
tray_h = 90 mm
z0 = -140 mm            # the tray's bottom face, in the board's frame (board bottom -150)
wall_h = tray_h - t     # walls stand above the bottom

def side() -> solid {
    # frame: x = depth (board face at -6, front at -76), y = height (z0 .. z0 + 90)
    body = Rectangle(bottom_left=(-t - tray_d, z0), width=tray_d, height=tray_h)
    corner = finger_edge(length=wall_h, thickness=t, finger=12 mm, start="gap",
                         rotation=90 deg, cx=-t - tray_d, cy=z0 + t + wall_h / 2)
    foot = tab_and_slot(part="tab", length=tray_d, thickness=t, tabs=2, tab=15 mm, screw=0,
                        rotation=180 deg, cx=-t - tray_d / 2, cy=z0)
}

assembly cap_catcher {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=180, height=300,
                                corner_radii=[20, 20, 0, 0])
        left_key = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=-60 mm, cy=130 mm)
        right_key = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=60 mm, cy=130 mm)
        opener_top = clearance_hole(size=4, cx=0 mm, cy=104 mm)
        opener_bottom = clearance_hole(size=4, cx=0 mm, cy=56 mm)
        tray_mortise = tab_and_slot(part="slot", length=tray_w + 2 * t, thickness=t, tabs=2,
                                    tab=30 mm, screw=0, cx=0 mm, cy=z0 + t / 2)
        drawing label {
            word = Text("CHEERS", position=(0, 10), size=22, font="serif:Bold",
                        valign="middle", fill=true)
        }
    }

    solid bottom {
        # frame: x across, y = depth (board's back face at 0, front edge at -82)
        body = Rectangle(bottom_left=(-(tray_w / 2 + t), -(tray_d + 2 * t)), width=tray_w + 2 * t,
                         height=tray_d + 2 * t)
        back_tabs = tab_and_slot(part="tab", length=tray_w + 2 * t, thickness=t, tabs=2,
                                 tab=30 mm, screw=0, cx=0 mm, cy=0 mm)
        front_mortise = tab_and_slot(part="slot", length=tray_w, thickness=t, tabs=2, tab=20 mm,
                                     screw=0, cx=0 mm, cy=-(t + tray_d) + t / 2)
        left_mortise = tab_and_slot(part="slot", length=tray_d, thickness=t, tabs=2, tab=15 mm,
                                    screw=0, rotation=90 deg, cx=-(tray_w / 2 - t / 2),
                                    cy=-t - tray_d / 2)
        right_mortise = tab_and_slot(part="slot", length=tray_d, thickness=t, tabs=2, tab=15 mm,
                                     screw=0, rotation=90 deg, cx=tray_w / 2 - t / 2,
                                     cy=-t - tray_d / 2)
    }

    solid front {
        # frame: x across, y = height (z0 .. z0 + 90)
        body = Rectangle(bottom_left=(-tray_w / 2, z0), width=tray_w, height=tray_h)
        left_corner = finger_edge(length=wall_h, thickness=t, finger=12 mm, start="tab",
                                  rotation=90 deg, cx=-tray_w / 2, cy=z0 + t + wall_h / 2)
        right_corner = finger_edge(length=wall_h, thickness=t, finger=12 mm, start="tab",
                                   rotation=-90 deg, cx=tray_w / 2, cy=z0 + t + wall_h / 2)
        foot = tab_and_slot(part="tab", length=tray_w, thickness=t, tabs=2, tab=20 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=z0)
    }

    left_side = side()
    right_side = side()

    # flat on the sheet: the board, then the tray's parts beside it
    RightOf(bottom, board, gap=10)
    AlignTop(bottom, board)
    Below(front, bottom, gap=10)
    AlignLeft(front, bottom)
    RightOf(left_side, bottom, gap=10)
    AlignTop(left_side, board)
    Below(right_side, left_side, gap=10)
    AlignLeft(right_side, left_side)

    # in 3D: board on the wall (its back face at y = 0), tray in front of it
    Place(board, position=(0, 0, 0), face="front", up="up")
    Place(bottom, position=(0, 0, z0), face="up")
    Place(front, position=(0, -(t + tray_d) + t, 0), face="front", up="up")
    Place(left_side, position=(-tray_w / 2, 0, 0), face="right", up="up")
    Place(right_side, position=(tray_w / 2 - t, 0, 0), face="right", up="up")

    # the request's numbers
    assert board.body.bb.width == 180 mm and board.body.bb.height == 300 mm, "board 180 x 300"
    assert board.right_key.head_hole.center.x - board.left_key.head_hole.center.x == 120 mm,
        "keyholes 120 apart"
    assert board.body.bb.top - board.left_key.head_hole.center.y == 20 mm, "keyholes 20 below top"
    assert board.opener_top.c.center.y - board.opener_bottom.c.center.y == 48 mm,
        "opener bolts 48 apart"
    assert board.body.bb.top - (board.opener_top.c.center.y + board.opener_bottom.c.center.y) / 2
        == 70 mm, "opener centred 70 below the top"
    assert front.body.bb.width == 150 mm, "tray 150 wide"
    assert left_side.body.bb.width == 70 mm, "tray 70 deep"
    assert front.body.bb.height == 90 mm, "tray 90 tall"
    assert bottom.body.bb.width == 162 mm and bottom.body.bb.height == 82 mm,
        "bottom 162 x 76 visible + 6 of tabs"
    assert front.body.bb.bottom - board.body.bb.bottom == 10 mm, "tray 10 above the board's bottom"
}
