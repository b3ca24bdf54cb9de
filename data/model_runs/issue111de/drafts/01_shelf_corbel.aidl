# Request: a pair of shelf corbels for a 180 mm deep floating oak shelf, cut from 6 mm birch ply
# (this file is one corbel; cut it twice). Each corbel is three glued parts:
# - a web (side view of the corbel) 160 mm deep x 140 mm tall overall: its back edge against the
#   wall, its top edge under the shelf, a 50 mm flat along the bottom and a 30 mm flat down the
#   front, joined by a concave cove of radius 110 mm; a 34 mm wide heart cut through it near the
#   back top corner (centre 45 mm from the wall, 95 mm up);
# - a wall plate 40 mm wide running from the bottom up to the shelf plate (134 mm), screwed to
#   the wall with four M4 countersunk screws (9 mm heads), 12 mm either side of the web and
#   45 mm above and below the plate's middle;
# - a shelf plate 160 x 40 mm under the shelf, screwed up into it with four M4 countersunk
#   screws, 12 mm either side of the web and 50 mm either side of the plate's middle.
# The web is joined to each plate by two 15 mm glued tabs through mortises.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm

param depth = 160 mm, min = 120 mm, max = 250 mm
param tall = 140 mm, min = 100 mm, max = 220 mm
param cove_r = 110 mm, min = 60 mm, max = 130 mm
t = 6 mm

# FIX after the first valid program: the unused template heart_hole (W0117, a leftover of
# mine: the heart is written in place in the web) is deleted.

assembly corbel {
    solid web {
        # side profile: x from the wall (tab tips at x = 0), y up from the bottom (tab tips at y = tall)
        cove = Arc(center=(depth, 0), radius=cove_r, start_angle=90 deg, end_angle=180 deg)
        bottom_edge = Line((0, 0), cove.end)
        front_edge = Line(cove.start, (depth, tall))
        top_edge = Line((depth, tall), (0, tall))
        back_edge = Line((0, tall), (0, 0))
        # tabs into the wall plate (panel towards +x) and up into the shelf plate (panel below)
        to_wall = tab_and_slot(part="tab", length=tall - t, thickness=t, tabs=2, tab=15 mm,
                               screw=0, rotation=90 deg, cx=0 mm, cy=(tall - t) / 2)
        to_shelf = tab_and_slot(part="tab", length=depth, thickness=t, tabs=2, tab=15 mm,
                                screw=0, rotation=0 deg, cx=depth / 2, cy=tall)
        hole heart {
            l = Hull(Circle(center=(45 - 8, 95 + 5), radius=9), Point(45, 95 - 16))
            r = Hull(Circle(center=(45 + 8, 95 + 5), radius=9), Point(45, 95 - 16))
            Rigid(self)
        }
    }

    solid wall_plate {
        body = Rectangle(center=(0, 0), width=40, height=tall - t)
        mortise = tab_and_slot(part="slot", length=tall - t, thickness=t, tabs=2, tab=15 mm,
                               screw=0, rotation=90 deg, cx=0 mm, cy=0 mm)
        s1 = clearance_hole(size=4, cx=-12 mm, cy=45 mm)
        s2 = clearance_hole(size=4, cx=12 mm, cy=45 mm)
        s3 = clearance_hole(size=4, cx=-12 mm, cy=-45 mm)
        s4 = clearance_hole(size=4, cx=12 mm, cy=-45 mm)
        Fixed(body)
        Countersink([s1, s2, s3, s4], diameter=9 mm)
    }

    solid shelf_plate {
        body = Rectangle(center=(0, 0), width=depth, height=40)
        mortise = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=15 mm,
                               screw=0, rotation=0 deg, cx=0 mm, cy=0 mm)
        s1 = clearance_hole(size=4, cx=-50 mm, cy=12 mm)
        s2 = clearance_hole(size=4, cx=50 mm, cy=12 mm)
        s3 = clearance_hole(size=4, cx=-50 mm, cy=-12 mm)
        s4 = clearance_hole(size=4, cx=50 mm, cy=-12 mm)
        Fixed(body)
        Countersink([s1, s2, s3, s4], diameter=9 mm)
    }

    # on the sheet: plates beside and above the web
    RightOf(wall_plate, web, gap=6)
    AlignBottom(wall_plate, web)
    Above(shelf_plate, web, gap=6)
    AlignLeft(shelf_plate, web)

    # in 3D: the wall is the plane y = 0, the corbel stands out towards the front (-y)
    Place(web, position=(3, 0, 0), face="left", up="up")
    Place(wall_plate, position=(0, 0, (tall - t) / 2), face="front", up="up")
    Place(shelf_plate, position=(0, -depth / 2, tall), face="down", up="left")

    # the request's numbers
    assert web.top_edge.length == 160 mm, "web 160 deep"
    assert web.back_edge.length == 140 mm, "web 140 tall"
    assert web.bottom_edge.length == 50 mm, "50 mm bottom flat"
    assert web.front_edge.length == 30 mm, "30 mm front flat"
    assert web.cove.radius == 110 mm, "cove radius 110"
    assert wall_plate.body.bb.height == 134 mm, "wall plate 134 long"
    assert wall_plate.body.bb.width == 40 mm and shelf_plate.body.bb.height == 40 mm, "plates 40 wide"
    assert shelf_plate.body.bb.width == 160 mm, "shelf plate 160 long"
    assert len(web.to_wall.gap) == 3 and len(web.to_shelf.gap) == 3, "two tabs each"
    assert web.heart.bb.width == 34 mm, "34 mm heart"
    assert abs(web.heart.bb.center_x - 45 mm) < 1 mm and abs(web.heart.bb.center_y - 95 mm) < 2 mm,
        "heart 45 from the wall, 95 up"
    assert wall_plate.s2.c.center.x - wall_plate.s1.c.center.x == 24 mm, "12 either side"
    assert wall_plate.s1.c.center.y - wall_plate.s3.c.center.y == 90 mm, "45 above and below"
    assert shelf_plate.s2.c.center.x - shelf_plate.s1.c.center.x == 100 mm, "50 either side"
}
