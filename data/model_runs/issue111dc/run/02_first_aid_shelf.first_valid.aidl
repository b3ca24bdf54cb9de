# Request: a first-aid shelf for the bathroom wall, from 3 mm white acrylic. A back plate
# 250 wide x 280 tall hangs on two keyholes (8 mm head, 4 mm slot 10 mm up) 160 mm apart,
# 30 mm below its top edge. Near the top a plus-sign cross 40 x 40 with 12 mm bars is cut
# through, centred 58 mm below the top, with "FIRST AID" engraved (bold, 10 mm, filled)
# under it. Two sides 90 deep x 180 tall, flush with the back's bottom, their outer faces
# 5 mm in from the back's side edges, stand out from it on 3 glued tabs (30 mm) each; their
# front edge rises straight 70 mm and then curves back in a hollow to 25 mm deep at the top.
# A shelf 10 mm above the bottom is tabbed into both sides (2 tabs of 20 mm) and the back
# (3 tabs of 30 mm); an 18 mm front rail, 3 mm behind the sides' front edge and its top 68 mm
# above the bottom, keeps bottles from falling, with one 10 mm tenon into each side.
# Five parts, all glued (no screws).

import "std/joints.aidl"
import "std/plates.aidl"

thickness 3 mm

T = 3 mm
back_w = 250 mm
back_h = 280 mm
depth = 90 mm
side_h = 180 mm
side_x = back_w / 2 - 5 mm - T / 2   # centre of a side's thickness on the back
inner = 2 * (side_x - T / 2)          # between the sides' inner faces
shelf_d = depth - T                   # shelf reaches the front of the rail's slot
shelf_z = 10 mm
rail_h = 18 mm
rail_top = 68 mm
rail_x = depth - T - T / 2            # rail's middle, in a side's depth

def side(s=1) -> solid {
    l1 = Line((0, 0), (s * depth, 0))
    l2 = Line((s * depth, 0), (s * depth, 70))
    a = Arc(start=(s * depth, 70), through=(s * 45.4, 117.9), end=(s * 25, side_h))
    l3 = Line((s * 25, side_h), (0, side_h))
    l4 = Line((0, side_h), (0, 0))
    strip = Rectangle(center=(-s * T / 2, side_h / 2), width=T, height=side_h)
    j = tab_and_slot(part="tab", length=side_h, thickness=T, tabs=3, tab=30 mm, screw=0,
                     rotation=s * 90 deg, cx=-s * T, cy=side_h / 2)
    shelf_slot = tab_and_slot(part="slot", length=shelf_d, thickness=T, tabs=2, tab=20 mm,
                              screw=0, cx=s * shelf_d / 2, cy=shelf_z + T / 2)
    rail_slot = tab_and_slot(part="slot", length=rail_h, thickness=T, tabs=1, tab=10 mm,
                             screw=0, rotation=90 deg, cx=s * rail_x, cy=rail_top - rail_h / 2)
    Rigid(self)
}

assembly first_aid_shelf {
    solid back {
        body = Rectangle(center=(0, back_h / 2), width=back_w, height=back_h)
        sr = tab_and_slot(part="slot", length=side_h, thickness=T, tabs=3, tab=30 mm, screw=0,
                          rotation=90 deg, cx=side_x, cy=side_h / 2)
        sl = tab_and_slot(part="slot", length=side_h, thickness=T, tabs=3, tab=30 mm, screw=0,
                          rotation=90 deg, cx=-side_x, cy=side_h / 2)
        ss = tab_and_slot(part="slot", length=inner, thickness=T, tabs=3, tab=30 mm, screw=0,
                          cx=0, cy=shelf_z + T / 2)
        k1 = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=80, cy=back_h - 30)
        k2 = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=-80, cy=back_h - 30)
        hole cross {
            h = Rectangle(center=(0, back_h - 58), width=40, height=12)
            v = Rectangle(center=(0, back_h - 58), width=12, height=40)
        }
        drawing label {
            t = Text("FIRST AID", position=(0, back_h - 94), size=10, font="sans:Bold", fill=true)
        }
    }

    right = side(s=1)
    left = side(s=-1)

    solid shelf {
        body = Rectangle(center=(0, -shelf_d / 2), width=inner, height=shelf_d)
        back_strip = Rectangle(center=(0, T / 2), width=inner, height=T)
        end_r = Rectangle(center=(inner / 2 + T / 2, -shelf_d / 2), width=T, height=shelf_d)
        end_l = Rectangle(center=(-inner / 2 - T / 2, -shelf_d / 2), width=T, height=shelf_d)
        jb = tab_and_slot(part="tab", length=inner, thickness=T, tabs=3, tab=30 mm, screw=0,
                          cx=0, cy=T)
        jr = tab_and_slot(part="tab", length=shelf_d, thickness=T, tabs=2, tab=20 mm, screw=0,
                          rotation=-90 deg, cx=inner / 2 + T, cy=-shelf_d / 2)
        jl = tab_and_slot(part="tab", length=shelf_d, thickness=T, tabs=2, tab=20 mm, screw=0,
                          rotation=90 deg, cx=-inner / 2 - T, cy=-shelf_d / 2)
    }

    solid rail {
        body = Rectangle(center=(0, rail_top - rail_h / 2), width=inner, height=rail_h)
        end_r = Rectangle(center=(inner / 2 + T / 2, rail_top - rail_h / 2), width=T, height=rail_h)
        end_l = Rectangle(center=(-inner / 2 - T / 2, rail_top - rail_h / 2), width=T, height=rail_h)
        jr = tab_and_slot(part="tab", length=rail_h, thickness=T, tabs=1, tab=10 mm, screw=0,
                          rotation=-90 deg, cx=inner / 2 + T, cy=rail_top - rail_h / 2)
        jl = tab_and_slot(part="tab", length=rail_h, thickness=T, tabs=1, tab=10 mm, screw=0,
                          rotation=90 deg, cx=-inner / 2 - T, cy=rail_top - rail_h / 2)
    }

    # on the sheet
    RightOf(right, back, gap=10)
    AlignBottom(right, back)
    RightOf(left, right, gap=10)
    AlignBottom(left, back)
    Above(shelf, back, gap=10)
    AlignLeft(shelf, back)
    Above(rail, shelf, gap=10)
    AlignLeft(rail, back)

    # on the wall: back's front face at y = 0, the bottom at z = 0
    Place(back, position=(0, T, 0), face="front", up="up")
    Place(right, position=(side_x + T / 2, 0, 0), face="left", up="up")
    Place(left, position=(-side_x - T / 2, 0, 0), face="right", up="up")
    Place(shelf, position=(0, 0, shelf_z), face="up", up="back")
    Place(rail, position=(0, -(depth - 2 * T), 0), face="front", up="up")

    # the request's numbers
    assert back.body.width == 250 mm and back.body.height == 280 mm, "back 250 x 280"
    assert abs(back.k1.head_hole.center.x - back.k2.head_hole.center.x) == 160 mm, "keyholes 160 apart"
    assert back.body.bb.top - back.k1.head_hole.center.y == 30 mm, "keyholes 30 below the top"
    assert back.cross.bb.width == 40 mm and back.cross.bb.height == 40 mm, "cross 40 x 40"
    assert back.body.bb.top - back.cross.h.center.y == 58 mm, "cross centred 58 below the top"
    assert back.label.bb.top < back.cross.bb.bottom - 2 mm, "label under the cross"
    assert back.label.bb.bottom > side_h + 2 mm, "label above the sides"
    assert right.l1.length == 90 mm and right.l4.length == 180 mm, "sides 90 x 180"
    assert back.body.bb.right - (side_x + T / 2) == 5 mm, "sides 5 in from the back's edges"
    assert right.l2.length == 70 mm, "front edge rises 70 straight"
    assert right.l3.length == 25 mm, "25 deep at the top"
    assert rail.body.height == 18 mm, "rail 18 tall"
    assert rail.body.bb.top == 68 mm, "rail top 68 above the bottom"
    assert depth - (rail_x + T / 2) == 3 mm, "rail 3 behind the front edge"
}
