# Request: a letterbox catcher (letter cage) for the inside of my front door, 4 mm birch ply,
# glued tab-and-slot joints. A back plate 320 wide x 250 tall screws to the door with four
# countersunk M4 screws 10 mm in from each side edge and 10 mm from the top and bottom edges;
# it has a 270 x 50 opening for the letter flap, centred, its middle 190 above the plate's
# bottom edge. The cage: a floor 20 above the plate's bottom edge, inside 300 wide and 110 deep
# (door plate to front lip), with a 10 mm ledge in front of the lip; two sides 120 tall above
# the floor, 60 deep at the top, the front edge rising straight for the lip's 70 then sloping
# back, the top front corner rounded R12; a front lip 70 tall above the floor with POST
# engraved (filled, bold sans, 30 tall). Every joint glued: tabs into mortises.

import "std/joints.aidl"
import "std/fasteners.aidl"

units mm
t = 4 mm
thickness t
kerf 0.15 mm

param W = 300 mm, min = 200 mm, max = 310 mm      # inside width
param D = 110 mm, min = 60 mm, max = 150 mm       # inside depth, door plate to lip
param LIP = 70 mm, min = 40 mm, max = 100 mm      # lip height above the floor
param SIDE_H = 120 mm, min = 90 mm, max = 140 mm  # side height above the floor
TOPD = 60 mm                                      # side depth at the top
FLOOR_Z = 20 mm                                   # floor's underside above the plate's bottom
LEDGE = 10 mm
CLR = 0.1 mm

# one side, drawn as seen from the right: its back edge (the tabs' tips, at the door) on x = 0,
# the front toward -x, the floor's top at y = 0 (its tabs' tips at y = -t)
def side_panel() -> solid {
    body = Polygon([(0, -t), (-(2 * t + D), -t), (-(2 * t + D), LIP), (-(t + TOPD), SIDE_H),
                    (0, SIDE_H)])
    back_j = tab_and_slot(part="tab", length=SIDE_H + t, thickness=t, tabs=3, tab=20 mm,
                          screw=0, rotation=-90 deg, cx=0 mm, cy=(SIDE_H - t) / 2)
    bottom_j = tab_and_slot(part="tab", length=2 * t + D, thickness=t, tabs=3, tab=20 mm,
                            screw=0, rotation=180 deg, cx=-(2 * t + D) / 2, cy=-t)
    Fillet(body.points[3], 12 mm)
}

assembly catcher {
    solid back {
        body = RoundedRectangle(center=(0, 125), width=320, height=250, corner_radius=6)
        hole letters {
            r = Rectangle(center=(0, 190), width=270, height=50)
        }
        hole screws {
            s1 = Circle(center=(-150, 10), diameter=4.5)
            s2 = Circle(center=(150, 10), diameter=4.5)
            s3 = Circle(center=(-150, 240), diameter=4.5)
            s4 = Circle(center=(150, 240), diameter=4.5)
        }
        Countersink(screws, diameter=9 mm)
        floor_m = tab_and_slot(part="slot", length=W + 2 * t, thickness=t, tabs=4, tab=30 mm,
                               screw=0, clearance=CLR, cx=0 mm, cy=FLOOR_Z + t / 2)
        right_m = tab_and_slot(part="slot", length=SIDE_H + t, thickness=t, tabs=3, tab=20 mm,
                               screw=0, clearance=CLR, rotation=90 deg,
                               cx=W / 2 + t / 2, cy=FLOOR_Z + t + (SIDE_H - t) / 2)
        left_m = tab_and_slot(part="slot", length=SIDE_H + t, thickness=t, tabs=3, tab=20 mm,
                              screw=0, clearance=CLR, rotation=90 deg,
                              cx=-(W / 2 + t / 2), cy=FLOOR_Z + t + (SIDE_H - t) / 2)
        Fixed(body)
    }

    solid floor {
        # FIX after the first valid program: the sides' mortises ran out through the floor's
        # edges (W0530): the floor now stands 6 mm past each side (320 wide, as the back
        # plate), its tabbed strip only as wide as the joint
        body = Rectangle(corner=(-(W / 2 + t + 6 mm), -(2 * t + D + LEDGE)),
                         opposite=(W / 2 + t + 6 mm, -t))
        strip = Rectangle(corner=(-(W / 2 + t), -t), opposite=(W / 2 + t, 0))
        back_j = tab_and_slot(part="tab", length=W + 2 * t, thickness=t, tabs=4, tab=30 mm,
                              screw=0, cx=0 mm, cy=0 mm)
        right_m = tab_and_slot(part="slot", length=2 * t + D, thickness=t, tabs=3, tab=20 mm,
                               screw=0, clearance=CLR, rotation=90 deg,
                               cx=W / 2 + t / 2, cy=-(2 * t + D) / 2)
        left_m = tab_and_slot(part="slot", length=2 * t + D, thickness=t, tabs=3, tab=20 mm,
                              screw=0, clearance=CLR, rotation=90 deg,
                              cx=-(W / 2 + t / 2), cy=-(2 * t + D) / 2)
        lip_m = tab_and_slot(part="slot", length=W, thickness=t, tabs=3, tab=40 mm,
                             screw=0, clearance=CLR, cx=0 mm, cy=-(t + D + t / 2))
    }

    right = side_panel()
    left = side_panel()

    solid lip {
        body = Rectangle(corner=(-W / 2, -t), opposite=(W / 2, LIP))
        j = tab_and_slot(part="tab", length=W, thickness=t, tabs=3, tab=40 mm, screw=0,
                         rotation=180 deg, cx=0 mm, cy=-t)
        drawing word {
            w = Text("POST", position=(0, LIP / 2), size=30, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    # 3D: the door's inside face is y = 0, the room toward -y, z up from the plate's bottom
    Place(back, position=(0, 0, 0), face="front", up="up")
    Place(floor, position=(0, 0, FLOOR_Z), face="up", up="back")
    Place(right, position=(W / 2, 0, FLOOR_Z + t), face="right", up="up")
    Place(left, position=(-(W / 2 + t), 0, FLOOR_Z + t), face="right", up="up")
    Place(lip, position=(0, -(t + D), FLOOR_Z + t), face="front", up="up")

    # flat on the sheet
    Below(floor, back, gap=10)
    AlignLeft(floor, back)
    RightOf(right, back, gap=10)
    AlignTop(right, back)
    Below(left, right, gap=10)
    AlignLeft(left, right)
    Below(lip, floor, gap=10)
    AlignLeft(lip, floor)

    # the request's numbers
    assert back.body.bb.width == 320 mm, "back plate 320 wide"
    assert back.body.bb.height == 250 mm, "back plate 250 tall"
    assert back.letters.r.width == 270 mm and back.letters.r.height == 50 mm, "flap opening 270 x 50"
    assert back.letters.r.center.y - back.body.bb.bottom == 190 mm, "opening's middle 190 up"
    assert back.screws.s1.center.x - back.body.bb.left == 10 mm, "screws 10 in from the side"
    assert back.screws.s1.center.y - back.body.bb.bottom == 10 mm, "screws 10 up"
    assert back.body.bb.top - back.screws.s3.center.y == 10 mm, "screws 10 down from the top"
    assert lip.body.bb.width == 300 mm, "inside 300 wide"
    assert lip.body.bb.height - t == 70 mm, "lip 70 above the floor"
    assert right.body.bb.height - t == 120 mm, "sides 120 above the floor"
    assert right.body.bb.width - 2 * t == 110 mm, "inside 110 deep"
    assert floor.body.bb.height + t - (2 * t + D) == 10 mm, "10 mm ledge"
}
