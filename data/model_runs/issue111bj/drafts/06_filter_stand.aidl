# Request: "A filtration stand for the school lab, 5 mm acrylic: a 300 x 90 mm shelf with
# three 45 mm holes for 75 mm funnels, 90 mm apart, numbered 1-3 (engraved, 6 mm) in front of
# each hole; its underside 150 mm above the bench so a 250 ml beaker fits under each funnel.
# Two end uprights, 200 mm tall, 130 mm wide at the foot and 90 at the top (r8 top corners),
# each with a 40 x 80 mm r10 hand hole; the shelf tabbed into them (two 20 mm tabs per end).
# A 50 mm tall back rail, 10 mm above the bench, flush with the back edge, tabbed into both
# uprights (one 25 mm tab per end), with 'FILTRATION' engraved on it (8 mm letters)."

import "std/joints.aidl"

thickness 5 mm

t = 5 mm
span = 300 mm         # between the uprights
shelf_d = 90 mm
shelf_z = 150 mm      # the shelf's underside above the bench
up_h = 200 mm
rail_h = 50 mm
rail_z = 10 mm

solid_x = span / 2 + t   # outside face of an upright

def upright() -> solid {
    side = Trapezoid(center=(0, up_h / 2), bottom_width=130, top_width=90, height=up_h)
    hole grip { r = RoundedRectangle(center=(0, 75), width=40, height=80, corner_radius=10) }
    shelf_slots = tab_and_slot(part="slot", length=shelf_d, thickness=t, tabs=2, tab=20 mm,
                               screw=0, cx=0, cy=shelf_z + t / 2)
    rail_slot = tab_and_slot(part="slot", length=rail_h, thickness=t, tabs=1, tab=25 mm,
                             screw=0, rotation=90 deg, cx=shelf_d / 2 - t / 2,
                             cy=rail_z + rail_h / 2)
    Fillet([side.top_left, side.top_right], 8)
}

assembly stand {
    solid shelf {
        board = Rectangle(center=(0, 0), width=span + 2 * t, height=shelf_d)
        for i in range(3) {
            hole funnel { c = Circle(center=((i - 1) * 90 mm, 0), diameter=45) }
        }
        drawing numbers {
            for i in range(3) {
                n = Text(str(i + 1), position=((i - 1) * 90 mm, -shelf_d / 2 + 6 mm), size=6)
            }
        }
        lt = tab_and_slot(part="tab", length=shelf_d, thickness=t, tabs=2, tab=20 mm, screw=0,
                          rotation=90 deg, cx=-solid_x, cy=0)
        rt = tab_and_slot(part="tab", length=shelf_d, thickness=t, tabs=2, tab=20 mm, screw=0,
                          rotation=-90 deg, cx=solid_x, cy=0)
    }
    left = upright()
    right = upright()
    solid rail {
        board = Rectangle(bottom_left=(-solid_x, rail_z), width=2 * solid_x, height=rail_h)
        lt = tab_and_slot(part="tab", length=rail_h, thickness=t, tabs=1, tab=25 mm, screw=0,
                          rotation=90 deg, cx=-solid_x, cy=rail_z + rail_h / 2)
        rt = tab_and_slot(part="tab", length=rail_h, thickness=t, tabs=1, tab=25 mm, screw=0,
                          rotation=-90 deg, cx=solid_x, cy=rail_z + rail_h / 2)
        drawing label {
            w = Text("FILTRATION", position=(0, rail_z + rail_h / 2), size=8, valign="middle")
        }
    }

    # on the sheet
    Below(rail, shelf, gap=5)
    AlignLeft(rail, shelf)
    Below(left, rail, gap=5)
    AlignLeft(left, rail)
    RightOf(right, left, gap=5)
    AlignBottom(right, left)

    # in 3D: x along the shelf, y front to back, z up
    Place(shelf, position=(0, 0, shelf_z))
    Place(left, rotation=(90 deg, 0, 90 deg), position=(-solid_x, 0, 0))
    Place(right, rotation=(90 deg, 0, 90 deg), position=(span / 2, 0, 0))
    Place(rail, rotation=(90 deg, 0, 0), position=(0, shelf_d / 2, 0))

    assert shelf.board.bb.width - 2 * t == 300 mm and shelf.board.bb.height == 90 mm,
        "300 x 90 shelf"
    assert len(shelf.funnel) == 3, "three funnels"
    assert shelf.funnel[0].c.diameter == 45 mm, "45 mm holes"
    assert shelf.funnel[1].c.center.x - shelf.funnel[0].c.center.x == 90 mm, "90 mm apart"
    assert shelf_z == 150 mm, "150 mm clear under the shelf"
    assert left.side.height == 200 mm and left.side.bottom_width == 130 mm and
        left.side.top_width == 90 mm, "uprights 200 tall, 130 to 90 wide"
    assert left.grip.r.bb.width == 40 mm and left.grip.r.bb.height == 80 mm, "40 x 80 hand hole"
    assert rail.board.bb.height == 50 mm, "50 mm rail"
}
