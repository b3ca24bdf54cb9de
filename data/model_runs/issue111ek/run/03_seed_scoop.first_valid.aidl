# Request: a bird-seed scoop from 3 mm birch ply, glued tab-and-slot. Inside 80 wide and 130
# long from the open mouth to the back wall; the floor stands 4 mm up inside the sides (so their
# mortises are closed) and runs 4 mm on behind the back wall; the back wall stands on the floor,
# 60 tall above it; the two sides slope from 60 above the floor at the back to 8 above it at the
# mouth, the mouth's top corner rounded R4. A handle fin stands upright on the centre line behind
# the back wall, 110 long and 40 tall, its bottom 10 above the floor's underside, with a 70 x 20
# hand slot and R8 corners at its far end; it goes through the back wall on two tenons. SEED is
# engraved (filled, bold sans, 12 tall) on the outside of the right side.

import "std/joints.aidl"

units mm
t = 3 mm
thickness t
kerf 0.15 mm

IW = 80 mm       # inside width
L = 130 mm       # mouth to the back wall's inside face
BACK_H = 60 mm   # back wall above the floor
MOUTH_H = 8 mm   # sides above the floor at the mouth
DROP = 4 mm      # sides below the floor's underside
TAIL = 4 mm      # floor and sides behind the back wall
HL = 110 mm      # handle length behind the back wall
HH = 40 mm       # handle height
HZ = 10 mm       # handle bottom above the floor's underside
CLR = 0.1 mm
SL = L + t + TAIL   # floor and side length, 137

# a side as seen from the right: the mouth at x = 0, the back at x = SL, the floor's underside
# at y = 0
def side_panel() -> solid {
    body = Polygon([(0, -DROP), (SL, -DROP), (SL, t + BACK_H), (0, t + MOUTH_H)])
    floor_m = tab_and_slot(part="slot", length=SL, thickness=t, tabs=4, tab=15 mm, screw=0,
                           clearance=CLR, cx=SL / 2, cy=t / 2)
    back_m = tab_and_slot(part="slot", length=BACK_H, thickness=t, tabs=2, tab=15 mm, screw=0,
                          clearance=CLR, rotation=90 deg, cx=L + t / 2, cy=t + BACK_H / 2)
    Fillet(body.points[3], 4 mm)
}

assembly scoop {
    solid floor {
        body = Rectangle(corner=(-(IW / 2 + t), 0), opposite=(IW / 2 + t, SL))
        right_j = tab_and_slot(part="tab", length=SL, thickness=t, tabs=4, tab=15 mm, screw=0,
                               rotation=-90 deg, cx=IW / 2 + t, cy=SL / 2)
        left_j = tab_and_slot(part="tab", length=SL, thickness=t, tabs=4, tab=15 mm, screw=0,
                              rotation=90 deg, cx=-(IW / 2 + t), cy=SL / 2)
        back_m = tab_and_slot(part="slot", length=IW, thickness=t, tabs=3, tab=15 mm, screw=0,
                              clearance=CLR, cx=0 mm, cy=L + t / 2)
    }

    right = side_panel()
    left = side_panel()

    solid back {
        body = Rectangle(corner=(-(IW / 2 + t), 0), opposite=(IW / 2 + t, BACK_H))
        foot = Rectangle(corner=(-IW / 2, -t), opposite=(IW / 2, 0))
        bottom_j = tab_and_slot(part="tab", length=IW, thickness=t, tabs=3, tab=15 mm, screw=0,
                                rotation=180 deg, cx=0 mm, cy=-t)
        right_j = tab_and_slot(part="tab", length=BACK_H, thickness=t, tabs=2, tab=15 mm,
                               screw=0, rotation=-90 deg, cx=IW / 2 + t, cy=BACK_H / 2)
        left_j = tab_and_slot(part="tab", length=BACK_H, thickness=t, tabs=2, tab=15 mm,
                              screw=0, rotation=90 deg, cx=-(IW / 2 + t), cy=BACK_H / 2)
        handle_m = tab_and_slot(part="slot", length=HH, thickness=t, tabs=2, tab=10 mm, screw=0,
                                clearance=CLR, rotation=90 deg, cx=0 mm, cy=HZ - t + HH / 2)
    }

    solid handle {
        body = Rectangle(corner=(-t, HZ), opposite=(HL, HZ + HH))
        j = tab_and_slot(part="tab", length=HH, thickness=t, tabs=2, tab=10 mm, screw=0,
                         rotation=90 deg, cx=-t, cy=HZ + HH / 2)
        hole grip {
            s = Slot(center=(HL - 45, HZ + HH / 2), length=70, width=20)
        }
        Fillet([body.top_right, body.bottom_right], 8 mm)
    }

    drawing word {
        w = Text("SEED", position=(0, 0), size=12, font="sans:Bold", fill=true)
    }
    CutInto(word, right)
    At(word.w.position, right.body.points[0], dx=90, dy=20)

    # 3D: x across, y from the mouth (0) to the back, z up from the floor's underside
    Place(floor, position=(0, 0, 0), face="up", up="back")
    Place(right, position=(IW / 2, 0, 0), face="right", up="up")
    Place(left, position=(-(IW / 2 + t), 0, 0), face="right", up="up")
    Place(back, position=(0, L + t, t), face="front", up="up")
    Place(handle, position=(-t / 2, L + t, 0), face="right", up="up")

    # flat on the sheet
    RightOf(right, floor, gap=10)
    AlignBottom(right, floor)
    Above(left, right, gap=10)
    AlignLeft(left, right)
    RightOf(back, right, gap=10)
    AlignBottom(back, right)
    Above(handle, back, gap=10)
    AlignLeft(handle, back)

    # the request's numbers
    assert floor.body.bb.width - 2 * t == 80 mm, "inside 80 wide"
    assert right.body.points[1].x - right.body.points[0].x - t - TAIL == 130 mm, "130 mouth to back"
    assert back.body.bb.height == 60 mm, "back wall 60 above the floor"
    assert right.body.points[2].y - t == 60 mm, "sides 60 above the floor at the back"
    assert right.body.points[3].y - t == 8 mm, "sides 8 above the floor at the mouth"
    assert right.body.points[0].y + DROP == 0 mm, "floor 4 up inside the sides"
    assert handle.body.bb.width - t == 110 mm and handle.body.bb.height == 40 mm, "handle 110 x 40"
    assert handle.grip.s.length == 70 mm and handle.grip.s.width == 20 mm, "hand slot 70 x 20"
}
