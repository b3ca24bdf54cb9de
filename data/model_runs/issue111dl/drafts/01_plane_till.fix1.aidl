# Request (workshop): a wall plane till for my hand planes, 6 mm birch ply, glued.
# A 450 x 300 back board hung on two keyholes (10 mm head, 5 mm shank, 12 mm slot) 350 mm
# apart, 40 mm below the top. A 450 wide, 180 deep shelf whose top is 180 mm above the back's
# bottom edge, held by three 40 mm tabs in mortises in the back and carried by two triangular
# brackets (170 deep, from 20 mm above the bottom up to the shelf) 180 mm either side of the
# middle; each bracket has two 30 mm tabs into the back and two into the shelf. A 40 mm high
# front lip stands on the shelf 7 mm in from its front edge on three 40 mm tabs, so the
# planes cannot slide off, with "HAND PLANES" engraved filled on its front.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

param width = 450 mm, min = 320 mm, max = 600 mm
param depth = 180 mm, min = 120 mm, max = 250 mm

T = 6 mm
back_h = 300 mm
shelf_top = 180 mm
bracket_x = 180 mm
bracket_low = 20 mm
bracket_depth = 170 mm
lip_h = 40 mm
lip_in = 7 mm      # from the shelf's front edge to the lip's front face

def bracket() -> solid {
    # side view: the wall on the right (x = 0 is the back board's front face), the shelf's
    # underside at y = shelf_top - T; tabs stand T past both edges
    body = Polygon([(T, bracket_low), (T, shelf_top - T), (0, shelf_top - T), (0, shelf_top),
                    (-bracket_depth, shelf_top), (-bracket_depth, shelf_top - 10)])
    wall = tab_and_slot(part="tab", length=shelf_top - T - bracket_low, thickness=T, tabs=2,
                        tab=30 mm, screw=0, rotation=-90 deg, cx=T,
                        cy=(bracket_low + shelf_top - T) / 2)
    top = tab_and_slot(part="tab", length=bracket_depth, thickness=T, tabs=2, tab=30 mm,
                       screw=0, cx=-bracket_depth / 2, cy=shelf_top)
}

assembly till {
    solid back {
        body = Rectangle(bottom_left=(-width / 2, 0), width=width, height=back_h)
        k1 = keyhole(head=10 mm, slot_width=5 mm, length=12 mm, cx=-175 mm, cy=back_h - 40 mm)
        k2 = keyhole(head=10 mm, slot_width=5 mm, length=12 mm, cx=175 mm, cy=back_h - 40 mm)
        shelf_slots = tab_and_slot(part="slot", length=width, thickness=T, tabs=3, tab=40 mm,
                                   screw=0, cx=0, cy=shelf_top - T / 2)
        left_slots = tab_and_slot(part="slot", length=shelf_top - T - bracket_low, thickness=T,
                                  tabs=2, tab=30 mm, screw=0, rotation=-90 deg, cx=-bracket_x,
                                  cy=(bracket_low + shelf_top - T) / 2)
        right_slots = tab_and_slot(part="slot", length=shelf_top - T - bracket_low, thickness=T,
                                   tabs=2, tab=30 mm, screw=0, rotation=-90 deg, cx=bracket_x,
                                   cy=(bracket_low + shelf_top - T) / 2)
        Fixed(body)
    }

    solid shelf {
        # y = 0 is the back board's front face; the tabs reach y = T, into the back
        body = Rectangle(bottom_left=(-width / 2, -depth), width=width, height=depth + T)
        to_back = tab_and_slot(part="tab", length=width, thickness=T, tabs=3, tab=40 mm,
                               screw=0, cx=0, cy=T)
        left_slots = tab_and_slot(part="slot", length=bracket_depth, thickness=T, tabs=2,
                                  tab=30 mm, screw=0, rotation=90 deg, cx=-bracket_x,
                                  cy=-bracket_depth / 2)
        right_slots = tab_and_slot(part="slot", length=bracket_depth, thickness=T, tabs=2,
                                   tab=30 mm, screw=0, rotation=90 deg, cx=bracket_x,
                                   cy=-bracket_depth / 2)
        lip_slots = tab_and_slot(part="slot", length=width, thickness=T, tabs=3, tab=40 mm,
                                 screw=0, cx=0, cy=-depth + lip_in + T / 2)
    }

    left = bracket()
    right = bracket()

    solid lip {
        body = Rectangle(bottom_left=(-width / 2, -T), width=width, height=lip_h + T)
        feet = tab_and_slot(part="tab", length=width, thickness=T, tabs=3, tab=40 mm,
                            screw=0, rotation=180 deg, cx=0, cy=-T)
        drawing label {
            word = Text("HAND PLANES", position=(0, lip_h / 2), size=16, font="sans:Bold",
                        valign="middle", fill=true)
        }
    }

    # on the sheet: side by side, for the flat view
    Below(shelf, back, gap=10)
    AlignLeft(shelf, back)
    RightOf(left, back, gap=10)
    RightOf(right, left, gap=10)
    Below(lip, shelf, gap=10)
    AlignLeft(lip, shelf)

    # in 3D: x across, y towards the wall, z up
    Place(back, position=(0, T, 0), face="front", up="up")
    Place(shelf, position=(0, 0, shelf_top - T), face="up")
    Place(left, position=(-bracket_x - T / 2, 0, 0), face="right", up="up")
    Place(right, position=(bracket_x - T / 2, 0, 0), face="right", up="up")
    # FIX after the first valid program: with face="front" the lip's front face is T in front
    # of its position, so the position is the lip's back face: lip_in + T from the front edge
    Place(lip, position=(0, -depth + lip_in + T, shelf_top), face="front", up="up")

    assert back.body.bb.width == 450 mm, "back 450 wide"
    assert back.body.bb.height == 300 mm, "back 300 high"
    assert back.k2.head_hole.center.x - back.k1.head_hole.center.x == 350 mm, "keyholes 350 apart"
    assert back.body.bb.top - back.k1.head_hole.center.y == 40 mm, "keyholes 40 below the top"
    assert shelf.body.bb.height - T == 180 mm, "shelf 180 deep"
    assert lip.body.bb.height - T == 40 mm, "lip 40 high"
    assert len(lip.feet.gap) == 4, "three tabs on the lip"
}
