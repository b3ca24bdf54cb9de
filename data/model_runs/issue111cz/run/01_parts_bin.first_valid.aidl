# Request (workshop): an open-front parts bin for the screw wall, cut from 3 mm birch ply and
# glued. Outside 100 mm wide, 150 mm deep; the sides are 80 mm tall at the back and slope down
# to 40 mm at the front (the top is level for the back 40 mm, then slopes). The floor sits
# 5 mm up from the sides' bottom edges; the back and the front lip stand 5 mm in from the
# sides' back and front edges, both standing on the floor. Every joint is glued tab-and-slot
# (tabs into closed slots). The back has two keyholes (8 mm head, 4 mm shank) 60 mm apart,
# 15 mm below its top, to hang the bin on screws. The front lip carries the engraved label
# "M4 x 16" 10 mm tall. 5 parts: 2 sides, floor, back, front lip.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 3 mm

param W = 100 mm, min = 60 mm, max = 200 mm       # outside width
param D = 150 mm, min = 100 mm, max = 250 mm      # depth
param H = 80 mm, min = 60 mm, max = 150 mm        # back height
param HF = 40 mm, min = 25 mm, max = 60 mm        # front height
T = 3 mm
SKIRT = 5 mm        # floor raised above the sides' bottom edge
INSET = 5 mm        # back and front stand this far in from the sides' ends
FLAT = 40 mm        # level part of the side's top, at the back

# the floor: x across (-W/2..W/2), y from front (0) to back (D)
# the back and front: x across, y = height above the sides' bottom edge
# the side: x from front (0) to back (D), y = height

def side_panel() -> solid {
    body = Polygon([(0, 0), (D, 0), (D, H), (D - FLAT, H), (0, HF)])
    floor_slots = tab_and_slot(part="slot", length=D, thickness=T, tabs=3, tab=20 mm, screw=0,
                               cx=D / 2, cy=SKIRT + T / 2)
    back_slots = tab_and_slot(part="slot", length=H - SKIRT, thickness=T, tabs=2, tab=15 mm,
                              screw=0, rotation=90 deg, cx=D - INSET - T / 2,
                              cy=SKIRT + (H - SKIRT) / 2)
    front_slots = tab_and_slot(part="slot", length=HF - SKIRT, thickness=T, tabs=1, tab=15 mm,
                               screw=0, rotation=90 deg, cx=INSET + T / 2,
                               cy=SKIRT + (HF - SKIRT) / 2)
}

def upright(h=80 mm, tabs=2, tab=15 mm) -> solid {
    body = Rectangle(bottom_left=(-W / 2, SKIRT), width=W, height=h - SKIRT)
    foot = tab_and_slot(part="tab", length=W, thickness=T, tabs=2, tab=20 mm, screw=0,
                        rotation=180 deg, cx=0, cy=SKIRT)
    left_tabs = tab_and_slot(part="tab", length=h - SKIRT, thickness=T, tabs=tabs, tab=tab,
                             screw=0, rotation=90 deg, cx=-W / 2, cy=SKIRT + (h - SKIRT) / 2)
    right_tabs = tab_and_slot(part="tab", length=h - SKIRT, thickness=T, tabs=tabs, tab=tab,
                              screw=0, rotation=-90 deg, cx=W / 2, cy=SKIRT + (h - SKIRT) / 2)
}

assembly parts_bin {
    left_side = side_panel()
    right_side = side_panel()

    solid floor {
        body = Rectangle(bottom_left=(-W / 2, 0), width=W, height=D)
        left_tabs = tab_and_slot(part="tab", length=D, thickness=T, tabs=3, tab=20 mm, screw=0,
                                 rotation=90 deg, cx=-W / 2, cy=D / 2)
        right_tabs = tab_and_slot(part="tab", length=D, thickness=T, tabs=3, tab=20 mm,
                                  screw=0, rotation=-90 deg, cx=W / 2, cy=D / 2)
        back_slots = tab_and_slot(part="slot", length=W, thickness=T, tabs=2, tab=20 mm,
                                  screw=0, cx=0, cy=D - INSET - T / 2)
        front_slots = tab_and_slot(part="slot", length=W, thickness=T, tabs=2, tab=20 mm,
                                   screw=0, cx=0, cy=INSET + T / 2)
    }

    back = upright(h=H, tabs=2, tab=15 mm)
    front = upright(h=HF, tabs=1, tab=15 mm)

    hole hang_left { k = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=-30, cy=H - 15) }
    hole hang_right { k = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=30, cy=H - 15) }
    CutInto(hang_left, back)
    CutInto(hang_right, back)

    drawing label {
        t = Text("M4 x 16", position=(0, SKIRT + (HF - SKIRT) / 2), size=10, valign="middle")
    }
    CutInto(label, front)

    # in 3D: x across, y from front (0) to back (D), z up
    Place(left_side, position=(-W / 2, 0, 0), face="right", up="up")
    Place(right_side, position=(W / 2 - T, 0, 0), face="right", up="up")
    Place(floor, position=(0, 0, SKIRT), face="up", up="back")
    Place(back, position=(0, D - INSET, 0), face="front", up="up")
    Place(front, position=(0, INSET + T, 0), face="front", up="up")

    # the request's numbers
    assert floor.body.bb.width == 100 mm, "outside width 100"
    assert left_side.body.bb.width == 150 mm, "depth 150"
    assert left_side.body.bb.height == 80 mm, "80 tall at the back"
    assert back.body.bb.top - left_side.body.bb.bottom == 80 mm, "back reaches the sides' top"
    assert front.body.bb.top - front.body.bb.bottom == 40 mm - 5 mm, "front lip 40 tall, on a 5 mm skirt"
    assert hang_right.k.head_hole.center.x - hang_left.k.head_hole.center.x == 60 mm, "keyholes 60 apart"
}
