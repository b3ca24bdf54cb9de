# Request: a wall-hung rack to show off three 260 mm dinner plates standing on edge, cut from
# 6 mm birch ply. A 500 x 120 mm shelf the plates stand on, 20 mm above the bottom of the
# brackets; a 500 x 200 mm back board they lean against, hung on the wall by two keyholes
# (9 mm head, 4.5 mm shank) 300 mm apart and 60 mm below its top; a 500 x 30 mm front rail
# 60 mm above the bottom (its top at 90 mm) that stops the plates sliding off. Two side
# brackets 140 mm deep and 200 mm tall, the front-top corner swept away in a concave curve
# from 40 mm at the top to 110 mm up the front edge. Everything glued: shelf, back board and
# rail have tabs through slots in the brackets (0.1 mm clearance), the tab tips flush with the
# brackets' outer faces, so the whole rack is 500 mm wide.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

param width = 500 mm, min = 300 mm, max = 800 mm
t = 6 mm
depth = 140 mm
tall = 200 mm
shelf_depth = 120 mm
shelf_z = 20 mm            # the shelf's underside above the bracket's bottom
rail_h = 30 mm
rail_z = 60 mm             # the rail's lower edge above the bracket's bottom
rail_x = 120 mm            # the rail's back face from the wall side of the bracket
fit = 0.1 mm

def bracket() -> solid {
    bottom = Line((0, 0), (depth, 0))
    front = Line((depth, 0), (depth, 110))
    sweep = Arc(start=(depth, 110), through=(80, 140), end=(40, tall))
    top = Line((40, tall), (0, tall))
    back = Line((0, tall), (0, 0))
    # back board: its middle plane 9 mm from the wall edge (a 6 mm wall behind it)
    back_slots = tab_and_slot(part="slot", length=tall, thickness=t, tabs=2, tab=30 mm,
                              screw=0, clearance=fit, rotation=90 deg, cx=t + t / 2, cy=tall / 2)
    # shelf: in front of the back board
    shelf_slots = tab_and_slot(part="slot", length=shelf_depth, thickness=t, tabs=2,
                               tab=30 mm, screw=0, clearance=fit,
                               cx=2 * t + shelf_depth / 2, cy=shelf_z + t / 2)
    # front rail
    rail_slot = tab_and_slot(part="slot", length=rail_h, thickness=t, tabs=1, tab=16 mm,
                             screw=0, clearance=fit, rotation=90 deg,
                             cx=rail_x + t / 2, cy=rail_z + rail_h / 2)
}

def board(w, h, tabs, tab) -> solid {
    body = Rectangle(center=(0, 0), width=w, height=h)
    left = tab_and_slot(part="tab", length=h, thickness=t, tabs=tabs, tab=tab, screw=0,
                        rotation=90 deg, cx=-w / 2, cy=0)
    right = tab_and_slot(part="tab", length=h, thickness=t, tabs=tabs, tab=tab, screw=0,
                         rotation=-90 deg, cx=w / 2, cy=0)
}

assembly rack {
    shelf = board(w=width, h=shelf_depth, tabs=2, tab=30 mm)
    solid back_board {
        b = board(w=width, h=tall, tabs=2, tab=30 mm)
        hang_l = keyhole(head=9 mm, slot_width=4.5 mm, length=12 mm, cx=-150 mm, cy=tall / 2 - 60 mm)
        hang_r = keyhole(head=9 mm, slot_width=4.5 mm, length=12 mm, cx=150 mm, cy=tall / 2 - 60 mm)
    }
    rail = board(w=width, h=rail_h, tabs=1, tab=16 mm)
    left = bracket()
    right = bracket()

    # flat on the sheet
    Above(back_board, shelf, gap=10)
    Above(rail, back_board, gap=10)
    AlignCenterX(back_board, shelf)
    AlignCenterX(rail, shelf)
    RightOf(left, shelf, gap=10)
    RightOf(right, left, gap=10)
    AlignBottom(left, shelf)
    AlignBottom(right, shelf)

    # in 3D: x along the rack, y out from the wall, z up; brackets stood on edge
    # (bracket x -> depth y, bracket y -> z, through its thickness -> x)
    Place(left, position=(-width / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(right, position=(width / 2 - t, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(shelf, position=(0, 2 * t + shelf_depth / 2, shelf_z))
    Place(back_board, position=(0, 2 * t, tall / 2), rotation=(90 deg, 0, 0))
    Place(rail, position=(0, rail_x + t, rail_z + rail_h / 2), rotation=(90 deg, 0, 0))

    # the request's numbers
    assert shelf.body.bb.width == 500 mm, "rack 500 mm wide, tab tip to tab tip"
    assert shelf.body.bb.height == 120 mm, "shelf 120 mm deep"
    assert back_board.b.body.bb.height == 200 mm, "back board 200 mm tall"
    assert rail.body.bb.height == 30 mm, "rail 30 mm tall"
    assert left.bb.width == 140 mm and left.bb.height == 200 mm, "brackets 140 x 200"
    assert back_board.hang_r.head_hole.center.x - back_board.hang_l.head_hole.center.x == 300 mm,
        "keyholes 300 mm apart"
    assert back_board.b.body.bb.top - back_board.hang_l.head_hole.center.y == 60 mm,
        "keyholes 60 mm below the top"
}
