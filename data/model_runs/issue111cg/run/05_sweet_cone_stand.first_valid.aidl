# Request (parties): a stand for six paper sweet cones (60 mm mouth, 180 mm long) on a party
# sweet table, cut from 6 mm ply. A 280 x 180 mm top (corners rounded 10 mm) with six 45 mm
# holes in 2 rows x 3 columns (80 mm apart across, 75 mm apart front to back) that catch the
# cones 45 mm below their mouths, its underside 150 mm above the table; "SWEET TREATS"
# engraved 9 mm tall along the front edge. A shelf 60 mm above the table with six 16 mm holes
# right under the big ones keeps the cone tips upright. Two legs 140 mm deep, 250 mm apart
# centre to centre, each with a 5-pointed star (36 mm across) cut out near the top and an arch
# 90 mm wide and 25 mm high cut from the foot; the top sits on two 30 mm tabs from each leg,
# the shelf hangs on two 25 mm tabs at each end through mortises in the legs. All glued.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
TOP_W = 280 mm
TOP_D = 180 mm
HEIGHT = 150 mm        # the top's underside above the table
SHELF_Z = 60 mm        # the shelf's underside above the table
LEG_X = 125 mm         # each leg's middle from the centre
LEG_D = 140 mm
SHELF_D = 120 mm
COL = 80 mm
ROW = 75 mm

def cone_holes(d=45 mm) -> hole {
    c = Circle(center=(-COL, ROW / 2), diameter=d)
    g = GridPattern(c, 2, 3, (COL, -ROW))
}

def leg() -> solid {
    body = Rectangle(bottom_left=(-LEG_D / 2, 0), width=LEG_D, height=HEIGHT + T)
    top_tabs = tab_and_slot(part="tab", length=LEG_D, thickness=T, tabs=2, tab=30 mm, screw=0,
                            cx=0 mm, cy=HEIGHT + T)
    shelf_seat = tab_and_slot(part="slot", length=SHELF_D, thickness=T, tabs=2, tab=25 mm,
                              screw=0, cx=0 mm, cy=SHELF_Z + T / 2)
    hole star {
        s = Star(center=(0, 112), points=5, outer_radius=18, inner_radius=8)
    }
    hole arch {
        e = Ellipse(center=(0, 0), rx=45, ry=25)
    }
}

assembly sweet_cone_stand {
    solid top {
        board = RoundedRectangle(center=(0, 0), width=TOP_W, height=TOP_D, corner_radius=10)
        cones = cone_holes()
        seat_l = tab_and_slot(part="slot", length=LEG_D, thickness=T, tabs=2, tab=30 mm,
                              screw=0, rotation=90 deg, cx=-LEG_X, cy=0 mm)
        seat_r = tab_and_slot(part="slot", length=LEG_D, thickness=T, tabs=2, tab=30 mm,
                              screw=0, rotation=90 deg, cx=LEG_X, cy=0 mm)
        drawing title {
            t = Text("SWEET TREATS", position=(0, -TOP_D / 2 + 14 mm), size=9, valign="middle")
        }
    }

    solid shelf {
        board = Rectangle(center=(0, 0), width=2 * (LEG_X + T / 2), height=SHELF_D)
        tips = cone_holes(d=16 mm)
        end_l = tab_and_slot(part="tab", length=SHELF_D, thickness=T, tabs=2, tab=25 mm, screw=0,
                             rotation=90 deg, cx=-LEG_X - T / 2, cy=0 mm)
        end_r = tab_and_slot(part="tab", length=SHELF_D, thickness=T, tabs=2, tab=25 mm, screw=0,
                             rotation=-90 deg, cx=LEG_X + T / 2, cy=0 mm)
    }

    leg_l = leg()
    leg_r = leg()

    # on the sheet
    Below(shelf, top, gap=10)
    AlignLeft(shelf, top)
    Below(leg_l, shelf, gap=10)
    AlignLeft(leg_l, shelf)
    RightOf(leg_r, leg_l, gap=10)
    AlignBottom(leg_r, leg_l)

    # in 3D: legs' x -> world y, y -> z, thickness -> x
    Place(top, position=(0, 0, HEIGHT))
    Place(shelf, position=(0, 0, SHELF_Z))
    Place(leg_l, position=(-LEG_X - T / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(leg_r, position=(LEG_X - T / 2, 0, 0), rotation=(90 deg, 0, 90 deg))

    # the request's numbers
    assert top.board.width == 280 mm and top.board.height == 180 mm, "top 280 x 180"
    assert len(top.cones.g) == 6 and len(shelf.tips.g) == 6, "six cones"
    assert top.cones.c.diameter == 45 mm and shelf.tips.c.diameter == 16 mm, "45 and 16 holes"
    assert top.cones.g[1].center.x - top.cones.g[0].center.x == 80 mm, "80 across"
    assert top.cones.g[0].center.y - top.cones.g[3].center.y == 75 mm, "75 front to back"
    assert top.seat_r.slot[0].bb.center_x - top.seat_l.slot[0].bb.center_x == 250 mm,
        "legs 250 apart"
    assert leg_l.body.height - T == 150 mm, "top's underside 150 up"
    assert leg_l.shelf_seat.slot[0].bb.bottom - leg_l.body.bb.bottom == 60 mm, "shelf 60 up"
    assert leg_l.body.width == 140 mm, "legs 140 deep"
    assert leg_l.star.s.outer_radius == 18 mm, "star 36 across"
    assert leg_l.arch.e.rx == 45 mm and leg_l.arch.e.ry == 25 mm, "arch 90 x 25"
}
