# Request: an indoor table for a hatchling tortoise called SHELDON. An open-topped
# finger-jointed box of 6 mm ply, 500 long x 300 deep x 150 tall outside (20 mm fingers),
# "SHELDON" engraved filled (bold, 30 mm) in the middle of the front. Inside, a hide: a
# tunnel of 3 mm ply 140 deep, bent from one strip 340 long by two living-hinge bands 30 wide
# centred 53 mm either side of the middle, each bent 90 degrees round a 15 mm inside radius,
# standing on the floor in the right half. A basking-lamp arm hooks over the back wall: a
# 6 mm upright (110 long, 80 tall) with a 6.4 mm slot 40 deep straddling the wall, tabbed
# (2 tabs of 20, glued) into a lamp shelf 80 wide x 180 long with 10 mm round corners and a
# 40 mm hole for an E27 lamp holder, the hole's centre 125 mm in front of the back wall's
# inside face.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

L = 500 mm
D = 300 mm
H = 150 mm
T = 6 mm
back_in = D / 2 - T          # the back wall's inside face, world y
lamp_y = back_in - 125 mm     # the lamp hole's centre, world y
slot_w = 6.4 mm

assembly tortoise_table {
    box = finger_box(length=L, depth=D, height=H, thickness=T, finger=20 mm, closed=false)

    drawing name {
        t = Text("SHELDON", position=(0, 0), size=30, font="sans:Bold", valign="middle", fill=true)
    }
    CenterInside(name, box.front)
    CutInto(name, box.front)

    solid hide {
        thickness 3 mm
        body = Rectangle(center=(0, 0), width=340, height=140)
        h1 = living_hinge(width=30 mm, height=140 mm, pitch=2 mm, cut=15 mm, bridge=3 mm,
                          cx=-53 mm, cy=0 mm)
        h2 = living_hinge(width=30 mm, height=140 mm, pitch=2 mm, cut=15 mm, bridge=3 mm,
                          cx=53 mm, cy=0 mm)
    }

    # the arm's upright, drawn with x = -(world y), y = height above the floor of the room
    solid hanger {
        body = Rectangle(corner=(-170, 110), opposite=(-60, 190))
        strip = Rectangle(corner=(-170, 190), opposite=(-60, 190 + T))
        hole wall_slot {
            s = Rectangle(corner=(-back_in - T - 0.2, 110), opposite=(-back_in + 0.2, H))
            o = Rectangle(corner=(-back_in - T - 0.2, 109), opposite=(-back_in + 0.2, 110),
                          overrun=true)
        }
        tabs = tab_and_slot(part="tab", length=110 mm, thickness=T, tabs=2, tab=20 mm, screw=0,
                            cx=-115 mm, cy=190 mm + T)
        Fillet(at=body.bottom_right, radius=20)
    }

    solid lamp_shelf {
        body = RoundedRectangle(center=(0, 80), width=80, height=180, corner_radius=10)
        hole lamp { c = Circle(center=(0, lamp_y), diameter=40) }
        slots = tab_and_slot(part="slot", length=110 mm, thickness=T, tabs=2, tab=20 mm, screw=0,
                             rotation=90 deg, cx=0 mm, cy=115 mm)
    }

    # on the sheet
    RightOf(hide, box, gap=10)
    AlignTop(hide, box)
    Below(hanger, hide, gap=10)
    AlignLeft(hanger, hide)
    RightOf(lamp_shelf, hanger, gap=10)
    AlignTop(lamp_shelf, hanger)

    # assembled: the box stands on z = 0; the floor's top at z = T
    Place(hide, position=(100, 0, T + 170), face="right", up="front")
    Bend(hide, at=-53, angle=90 deg, radius=15)
    Bend(hide, at=53, angle=90 deg, radius=15)
    Place(hanger, position=(T / 2, 0, 0), face="left", up="up")
    Place(lamp_shelf, position=(0, 0, 190), face="up", up="back")

    # the request's numbers
    assert box.front.bb.width == 500 mm and box.front.bb.height == 150 mm, "500 long, 150 tall"
    assert box.left.bb.height == 300 mm, "300 deep"
    assert hide.body.width == 340 mm and hide.body.height == 140 mm, "hide strip 340 x 140"
    assert hide.h1.width >= pi / 2 * (15 mm + 1.5 mm), "hinge band covers the 90 deg bend"
    assert name.t.size == 30 mm, "name 30 tall"
    assert hanger.body.width == 110 mm and hanger.body.height == 80 mm, "upright 110 x 80"
    assert hanger.wall_slot.s.width == 6.4 mm, "wall slot 6.4 wide"
    assert H - hanger.body.bb.bottom == 40 mm, "wall slot 40 deep"
    assert lamp_shelf.body.width == 80 mm and lamp_shelf.body.height == 180 mm, "shelf 80 x 180"
    assert lamp_shelf.lamp.c.diameter == 40 mm, "lamp hole 40"
    assert back_in - lamp_shelf.lamp.c.center.y == 125 mm, "lamp 125 in front of the back wall"
    assert lamp_shelf.lamp.c.center.y + 20 mm < 60 mm, "lamp hole clear of the upright"
}
