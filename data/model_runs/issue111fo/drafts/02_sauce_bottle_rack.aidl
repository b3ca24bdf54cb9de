# Request: a rack that holds four 500 ml squeeze bottles (65 mm across) upside down, in
# 4 mm birch ply, glued. Two end panels 120 mm wide x 180 mm tall with an arched top (the
# straight sides 150 tall) and a 90 x 25 mm hand slot centred 152 mm up. A base 300 mm long
# between the end panels and 110 deep, standing 10 mm off the table, and a shelf 110 mm
# above the base's top face, both with two 25 mm tenons at each end through the end panels.
# The shelf has four 68 mm holes at 72 mm pitch; the base has a 40 mm engraved ring under
# each hole for the cap and the names KETCHUP, MUSTARD, MAYO, BBQ engraved in front of them.

import "std/joints.aidl"

thickness 4 mm

T = 4 mm          # ply
INNER = 300 mm    # between the end panels
DEPTH = 110 mm
PITCH = 72 mm
BASE_Z = 10 mm    # base's underside above the table
GAP = 110 mm      # base's top face to the shelf's underside
SHELF_Z = BASE_Z + T + GAP
NAMES = ["KETCHUP", "MUSTARD", "MAYO", "BBQ"]

def end_panel() -> solid {
    l_bottom = Line((-60, 0), (60, 0))
    l_right = Line((60, 0), (60, 150))
    top = Arc(start=(60, 150), through=(0, 180), end=(-60, 150))
    l_left = Line((-60, 150), (-60, 0))
    hole grip {
        s = Slot(center=(0, 152), length=90, width=25)
    }
    base_slots = tab_and_slot(part="slot", length=DEPTH, thickness=T, tabs=2, tab=25 mm,
                              screw=0, cx=0 mm, cy=BASE_Z + T / 2)
    shelf_slots = tab_and_slot(part="slot", length=DEPTH, thickness=T, tabs=2, tab=25 mm,
                               screw=0, cx=0 mm, cy=SHELF_Z + T / 2)
}

# a board running between the end panels, tenons at both ends (x = +-(INNER/2 + T))
def board() -> solid {
    body = Rectangle(center=(0, 0), width=INNER + 2 * T, height=DEPTH)
    left_tabs = tab_and_slot(part="tab", length=DEPTH, thickness=T, tabs=2, tab=25 mm,
                             screw=0, rotation=90 deg, cx=-(INNER / 2 + T), cy=0 mm)
    right_tabs = tab_and_slot(part="tab", length=DEPTH, thickness=T, tabs=2, tab=25 mm,
                              screw=0, rotation=-90 deg, cx=INNER / 2 + T, cy=0 mm)
}

assembly sauce_rack {
    left_end = end_panel()
    right_end = end_panel()
    base = board()
    shelf = board()


    hole bottle_holes {
        for i in range(4) {
            h = Circle(center=((i - 1.5) * PITCH, 0), diameter=68)
        }
    }
    CenterInside(bottle_holes, shelf.body)
    CutInto(bottle_holes, shelf)
    # FIX after the first valid program: the marks were a drawing inside an empty solid
    # (W0509), not engraved on the base; now a drawing cut into the base.
    drawing marks {
        for i in range(4) {
            ring = Circle(center=((i - 1.5) * PITCH, 0), diameter=40)
            name = Text(NAMES[i], position=((i - 1.5) * PITCH, -42), size=7, valign="middle")
        }
    }
    AlignCenterX(marks.ring[0], bottle_holes.h[0])
    marks.ring[0].center.y == base.body.center.y
    CutInto(marks, base)

    # flat on the sheet
    RightOf(right_end, left_end, gap=10)
    AlignBottom(right_end, left_end)
    Above(base, left_end, gap=10)
    AlignLeft(base, left_end)
    Above(shelf, base, gap=10)
    AlignLeft(shelf, base)

    # in 3D
    Place(base, position=(0, 0, BASE_Z), face="up")
    Place(shelf, position=(0, 0, SHELF_Z), face="up")
    Place(left_end, position=(-INNER / 2, 0, 0), face="left", up="up")
    Place(right_end, position=(INNER / 2, 0, 0), face="right", up="up")

    assert len(bottle_holes.h) == 4, "four bottles"
    assert bottle_holes.h[0].diameter == 68 mm, "68 mm holes"
    assert bottle_holes.h[1].center.x - bottle_holes.h[0].center.x == 72 mm, "72 mm pitch"
    assert SHELF_Z - (BASE_Z + T) == 110 mm, "shelf 110 above the base's top"
    assert base.body.bb.width - 2 * T == 300 mm, "300 between the ends"
    assert left_end.bb.height == 180 mm, "ends 180 tall"
    assert left_end.bb.width == 120 mm, "ends 120 wide"
}
