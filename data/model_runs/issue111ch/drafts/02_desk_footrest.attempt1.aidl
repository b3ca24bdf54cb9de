# Request (office): an under-desk footrest in 12 mm birch ply. A top board 450 mm wide and
# 320 mm deep (15 mm corners) sloping at 15 degrees, its front edge 60 mm off the floor; six
# grip slots 300 x 8 mm across it, 40 mm apart. Two sides 40 mm in from the board's ends,
# each standing on two feet (an arch 169 mm wide and 25 mm high under it); the sides' sloping
# top edges carry two 40 mm tabs each, glued through mortises in the board. Two stretchers
# 40 mm tall join the sides 35 mm in from the front and back, each with a 24 mm through
# tenon at both ends in a mortise in the side, 28 mm up (its centre).

import "std/joints.aidl"

units mm
thickness 12 mm

param width = 450 mm, min = 380 mm, max = 600 mm
param depth = 320 mm, min = 260 mm, max = 400 mm
param tilt = 15 deg, min = 8 deg, max = 22 deg
param front_h = 60 mm, min = 45 mm, max = 90 mm
param inset = 40 mm, min = 30 mm, max = 60 mm

t = 12 mm
run = depth * cos(tilt)                 # the side's footprint
back_h = front_h + depth * sin(tilt)    # the side's height at the back (tab tips)
side_x = width / 2 - inset              # the sides' mid-planes, either side of centre
str_y = 28 mm                           # the stretchers' centre height
str_h = 40 mm
str_in = 35 mm

solid top {
    board = RoundedRectangle(center=(0, depth / 2), width=width, height=depth, corner_radius=15)
    left_m = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=40 mm, screw=0,
                          rotation=90 deg, cx=-side_x, cy=depth / 2)
    right_m = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=40 mm, screw=0,
                           rotation=90 deg, cx=side_x, cy=depth / 2)
    hole grip {
        g = Slot(center=(0, depth / 2 - 100), length=300, width=8)
    }
    grips = LinearPattern(grip, 6, (0, 40))
}

def side() -> solid {
    body = Polygon([(0, 0), (run, 0), (run, back_h), (0, front_h)])
    joint = tab_and_slot(part="tab", length=depth, thickness=t, tabs=2, tab=40 mm, screw=0,
                         rotation=tilt, cx=run / 2, cy=(front_h + back_h) / 2)
    hole arch {
        e = Ellipse(center=(run / 2, 0), rx=84.5, ry=25)
    }
    front_m = tab_and_slot(part="slot", length=str_h, thickness=t, tabs=1, tab=24 mm, screw=0,
                           rotation=90 deg, cx=str_in, cy=str_y)
    back_m = tab_and_slot(part="slot", length=str_h, thickness=t, tabs=1, tab=24 mm, screw=0,
                          rotation=90 deg, cx=run - str_in, cy=str_y)
}

def stretcher() -> solid {
    bar = Rectangle(center=(0, str_y), width=2 * side_x + t, height=str_h)
    left_t = tab_and_slot(part="tab", length=str_h, thickness=t, tabs=1, tab=24 mm, screw=0,
                          rotation=90 deg, cx=-(side_x + t / 2), cy=str_y)
    right_t = tab_and_slot(part="tab", length=str_h, thickness=t, tabs=1, tab=24 mm, screw=0,
                           rotation=-90 deg, cx=side_x + t / 2, cy=str_y)
}

assembly footrest {
    board = top
    left = side()
    right = side()
    front = stretcher()
    back = stretcher()

    # flat on the sheet
    Below(left, board, gap=10)
    RightOf(right, left, gap=10)
    AlignLeft(left, board)
    Below(front, left, gap=10)
    Below(back, front, gap=10)
    AlignLeft(front, board)
    AlignLeft(back, board)

    # in 3D: x across, y from front to back, z up
    Place(left, rotation=(90 deg, 0, 90 deg), position=(-side_x - t / 2, 0, 0))
    Place(right, rotation=(90 deg, 0, 90 deg), position=(side_x - t / 2, 0, 0))
    Place(board, rotation=(tilt, 0, 0), position=(0, t * sin(tilt), front_h - t * cos(tilt)))
    Place(front, rotation=(90 deg, 0, 0), position=(0, str_in + t / 2, 0))
    Place(back, rotation=(90 deg, 0, 0), position=(0, run - str_in + t / 2, 0))

    assert board.board.bb.width == 450 mm and board.board.bb.height == 320 mm, "top 450 x 320"
    assert len(board.grips) == 6, "six grip slots"
    assert board.grips[1].g.center.y - board.grips[0].g.center.y == 40 mm, "slots 40 apart"
    assert abs(left.body.bb.height - (60 mm + 320 mm * sin(15 deg))) < 0.01 mm, "15 deg slope from 60 mm"
    assert width / 2 - side_x == 40 mm, "sides 40 mm in from the ends"
    assert front.bar.bb.height == 40 mm, "stretchers 40 mm tall"
}
