# Request: a stand for a wedding's paper confetti cones (cones 50 mm across the mouth,
# 150 mm long), 6 mm birch ply, 4 parts glued with through tenons (0.1 mm clearance).
# - Top: 300 x 200, R10 corners, 12 holes of 40 mm in 3 rows of 4, 65 mm apart across and
#   55 mm apart front to back, the grid centred across and its front row 55 mm behind the
#   middle's front... (rows at y = -45, 10, 65 from the centre); "LOVE IS IN THE AIR" engraved
#   filled, serif bold 9 mm, centred 85 mm in front of the middle (baseline).
# - Two ends, 200 wide x 140 tall to the top's underside, the top's 6 mm on them (146
#   overall): two 40 mm tenons up through the top (its mortises centred 135 mm either side
#   of the middle); feet: a 120 mm wide, 12 mm high arch cut from the bottom edge, its
#   inner corners R8.
# - Shelf: 160 deep, its top face 30 mm above the floor, held by two 40 mm tenons at each
#   end through the ends; 12 holes of 10 mm right under the top's holes, to seat the tips.

import "std/joints.aidl"

thickness 6 mm

def end_panel() -> solid {
    body = Polygon([(-100, 0), (-60, 0), (-60, 12), (60, 12), (60, 0), (100, 0), (100, 146),
                    (-100, 146)])
    Fillet(body.points[2], 8)
    Fillet(body.points[3], 8)
    up_tenons = tab_and_slot(part="tab", length=200 mm, thickness=6 mm, tabs=2, tab=40 mm,
                             screw=0, cx=0 mm, cy=146 mm)
    shelf_slots = tab_and_slot(part="slot", length=160 mm, thickness=6 mm, tabs=2, tab=40 mm,
                               screw=0, clearance=0.1 mm, cx=0 mm, cy=27 mm)
}

assembly confetti_stand {
    solid top {
        plate = RoundedRectangle(center=(0, 0), width=300, height=200, corner_radius=10)
        hole cone {
            c = Circle(center=(-97.5, -45), diameter=40)
        }
        cones = GridPattern(cone, 3, 4, (65, 55))
        left_mortise = tab_and_slot(part="slot", length=200 mm, thickness=6 mm, tabs=2,
                                    tab=40 mm, screw=0, clearance=0.1 mm, rotation=90 deg,
                                    cx=-135 mm, cy=0 mm)
        right_mortise = tab_and_slot(part="slot", length=200 mm, thickness=6 mm, tabs=2,
                                     tab=40 mm, screw=0, clearance=0.1 mm, rotation=90 deg,
                                     cx=135 mm, cy=0 mm)
        drawing motto {
            t = Text("LOVE IS IN THE AIR", position=(0, -85), size=9, font="serif:Bold",
                     fill=true)
        }
        Fixed(plate)
    }

    solid shelf {
        board = Rectangle(center=(0, 0), width=276, height=160)
        hole tip {
            c = Circle(center=(-97.5, -45), diameter=10)
        }
        tips = GridPattern(tip, 3, 4, (65, 55))
        left_tenons = tab_and_slot(part="tab", length=160 mm, thickness=6 mm, tabs=2, tab=40 mm,
                                   screw=0, rotation=90 deg, cx=-138 mm, cy=0 mm)
        right_tenons = tab_and_slot(part="tab", length=160 mm, thickness=6 mm, tabs=2, tab=40 mm,
                                    screw=0, rotation=-90 deg, cx=138 mm, cy=0 mm)
        Fixed(board)
    }

    left_end = end_panel()
    right_end = end_panel()

    # flat on the sheet
    Below(shelf, top, gap=8)
    AlignLeft(shelf, top)
    RightOf(left_end, top, gap=8)
    AlignTop(left_end, top)
    Below(right_end, left_end, gap=8)
    AlignLeft(right_end, left_end)

    # assembled: ends standing across x at +-135, top on them, shelf between them
    Place(top, position=(0, 0, 140), face="up")
    Place(shelf, position=(0, 0, 24), face="up")
    Place(left_end, position=(-132, 0, 0), face="left", up="up")
    Place(right_end, position=(132, 0, 0), face="right", up="up")

    assert len(top.cones) == 12 and len(shelf.tips) == 12, "12 cones"
    assert top.cones[1].c.center.x - top.cones[0].c.center.x == 65 mm, "65 across"
    assert top.cones[4].c.center.y - top.cones[0].c.center.y == 55 mm, "55 front to back"
    assert top.cones[0].c.diameter == 40 mm and shelf.tips[0].c.diameter == 10 mm, "hole sizes"
    assert top.plate.width == 300 mm and top.plate.height == 200 mm, "top 300 x 200"
    assert top.cones[5].c.center.x - top.plate.center.x == shelf.tips[5].c.center.x - shelf.board.center.x, "tips under the cones"
    assert top.cones[5].c.center.y - top.plate.center.y == shelf.tips[5].c.center.y - shelf.board.center.y, "tips under the cones"
    assert distance(top.motto, top.cone) >= 5 mm, "motto clear of the holes"
    assert distance(top.cones[3], top.right_mortise) >= 5 mm, "holes clear of the mortises"
    assert left_end.body.bb.height == 140 mm + 6 mm, "146 overall"
    assert 140 mm + 6 mm - 30 mm <= 150 mm - 30 mm, "a cone (40 mm wide 30 mm below its mouth) reaches the shelf's tip holes"
}
