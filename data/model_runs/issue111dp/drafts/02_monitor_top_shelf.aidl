# Request (office): a small shelf that sits on top of a monitor, for a webcam, a plant and
# sticky notes; 6 mm ply. Shelf board 300 x 110 mm, R10 front corners, square back corners.
# It rests on two brackets 200 mm apart (centre to centre) that straddle the monitor's top
# edge: each bracket is 110 mm deep, has a 22 mm wide slot for the monitor (up 46 mm from
# the foot of the back leg), a front lip 12 mm thick that comes only 8 mm down the bezel,
# a back leg 20 mm wide going 46 mm down the monitor's back, and a diagonal brace from the
# back leg's foot up to the shelf's back; corners R3 (R1 in the slot). Each bracket's top
# edge has two 20 mm tabs glued into mortises in the shelf. A back rail 300 x 40 mm stands
# at the shelf's back (its back face 8 mm in from the shelf's back edge) on two 40 mm tabs;
# it carries the name "MAYA" engraved filled, 22 mm tall, bold.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
shelf_w = 300 mm
depth = 110 mm
rise = 60 mm              # bracket's foot to the shelf's underside
span = 200 mm             # bracket centre to bracket centre
rail_h = 40 mm
rail_y = depth / 2 - 8 mm - t / 2

def bracket() -> solid {
    body = Polygon([(0, rise + t), (0, 38), (12, 38), (12, 46), (34, 46), (34, 0), (54, 0),
                    (depth, 48), (depth, rise + t)])
    top = tab_and_slot(part="tab", length=depth, thickness=t, tabs=2, tab=20 mm, screw=0,
                       cx=depth / 2, cy=rise + t)
    Fixed(body)
    Fillet([body.points[1], body.points[2], body.points[5], body.points[6]], 3 mm)
    Fillet(body.points[7], 3 mm)
    Fillet([body.points[3], body.points[4]], 1 mm)
    assert body.points[4].x - body.points[3].x == 22 mm, "monitor slot 22 mm"
    assert body.points[3].y - body.points[2].y == 8 mm, "lip 8 mm down the bezel"
    assert body.points[5].x - body.points[4].x == 0 mm and body.points[6].x - body.points[5].x == 20 mm
}

assembly monitor_shelf {
    solid shelf {
        board = RoundedRectangle(center=(0, 0), width=shelf_w, height=depth,
                                 corner_radii=[0, 0, 10, 10])
        ml = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=20 mm, screw=0,
                          rotation=90 deg, cx=-span / 2, cy=0)
        mr = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=20 mm, screw=0,
                          rotation=90 deg, cx=span / 2, cy=0)
        mb = tab_and_slot(part="slot", length=shelf_w, thickness=t, tabs=2, tab=40 mm,
                          screw=0, cx=0, cy=rail_y)
        Fixed(board)
        assert board.bb.width == 300 mm and board.bb.height == 110 mm
        assert mr.slot[0].bb.center_x - ml.slot[0].bb.center_x == 200 mm, "brackets 200 apart"
        assert board.bb.top - mb.slot[0].bb.top == 8 mm, "rail 8 mm in from the back"
    }

    left = bracket()
    right = bracket()

    solid rail {
        body = Rectangle(center=(0, 0), width=shelf_w, height=rail_h + t)
        feet = tab_and_slot(part="tab", length=shelf_w, thickness=t, tabs=2, tab=40 mm,
                            screw=0, rotation=180 deg, cx=0, cy=-(rail_h + t) / 2)
        drawing name {
            n = Text("MAYA", position=(0, t / 2), size=22, font="sans:Bold", valign="middle",
                     fill=true)
        }
        Fixed(body)
    }

    # flat on the sheet
    Above(left, shelf, gap=8)
    AlignLeft(left, shelf)
    RightOf(right, left, gap=8)
    AlignBottom(right, left)
    Above(rail, left, gap=8)
    AlignLeft(rail, shelf)

    # assembled: brackets stand across the monitor's top, the shelf on them, the rail behind
    Place(shelf, position=(0, 0, rise), face="up", up="back")
    Place(left, position=(-span / 2 - t / 2, -depth / 2, 0), face="right", up="up")
    Place(right, position=(span / 2 - t / 2, -depth / 2, 0), face="right", up="up")
    Place(rail, position=(0, rail_y + t / 2, rise + (rail_h + t) / 2), face="front", up="up")
}
