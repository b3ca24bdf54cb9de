# Request: a wall rack for my 8 combination spanners (8, 10, 12, 13, 14, 17, 19 and 22 mm),
# cut from 6 mm birch ply. A 320 x 140 mm back plate with 8 mm rounded corners, screwed to the
# wall through four 4.5 mm holes countersunk to 9 mm (at 100 mm either side of the middle,
# 55 mm above and 50 mm below the centre). A 320 mm shelf sticking out 70 mm from the back, its
# top 40 mm above the back's centre, glued into the back with three 40 mm tabs. In the shelf
# 8 U-slots open at the front, 40 mm deep, 34 mm apart (centred), 11, 12, 13, 14, 16, 18, 20
# and 23 mm wide, the spanner's size engraved 7 mm high behind each slot. Two 60 x 80 mm
# triangle brackets under the shelf, 140 mm either side of the middle, tabbed into the back
# and the shelf. "SPANNERS" engraved 14 mm high on the back below the shelf. Round the shelf's
# two front corners 5 mm.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
WIDTHS = [11, 12, 13, 14, 16, 18, 20, 23]
SIZES = ["8", "10", "12", "13", "14", "17", "19", "22"]
PITCH = 34 mm
SLOT_DEPTH = 40 mm
SHELF_DEPTH = 70 mm

def bracket() -> solid {
    # drawn to the tips of its tabs: the back edge at x = -6 (into the back plate),
    # the top edge at y = 40 (into the shelf, whose underside is at y = 34)
    body = Polygon([(-6, 40), (60, 40), (-6, -46)])
    top_tab = tab_and_slot(part="tab", length=66 mm, thickness=T, tabs=1, tab=30 mm, screw=0,
                           cx=27 mm, cy=40 mm)
    back_tab = tab_and_slot(part="tab", length=86 mm, thickness=T, tabs=1, tab=40 mm, screw=0,
                            rotation=90 deg, cx=-6 mm, cy=-3 mm)
}

assembly rack {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=320, height=140, corner_radius=8)
        shelf_slots = tab_and_slot(part="slot", length=320 mm, thickness=T, tabs=3, tab=40 mm,
                                   screw=0, cx=0 mm, cy=37 mm)
        left_slot = tab_and_slot(part="slot", length=86 mm, thickness=T, tabs=1, tab=40 mm,
                                 screw=0, rotation=90 deg, cx=-140 mm, cy=-3 mm)
        right_slot = tab_and_slot(part="slot", length=86 mm, thickness=T, tabs=1, tab=40 mm,
                                  screw=0, rotation=90 deg, cx=140 mm, cy=-3 mm)
        hole screws {
            for p in [(-100, 55), (100, 55), (-100, -50), (100, -50)] {
                c = Circle(center=p, diameter=4.5)
            }
        }
        Countersink(screws, diameter=9 mm)
        drawing label {
            t = Text("SPANNERS", position=(0, -35), size=14, valign="middle")
        }
    }

    solid shelf {
        # y = -6 .. 0: the tabs in the back plate; y = 0 .. 70: the shelf
        body = Rectangle(bottom_left=(-160, -6), width=320, height=76)
        tabs = tab_and_slot(part="tab", length=320 mm, thickness=T, tabs=3, tab=40 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=-6 mm)
        hole spanner {
            for i in range(8) {
                u = Slot(center=(-3.5 * PITCH + i * PITCH, SHELF_DEPTH - SLOT_DEPTH + 45 / 2),
                         length=45, width=WIDTHS[i], rotation=90 deg)
            }
        }
        left_mortise = tab_and_slot(part="slot", length=66 mm, thickness=T, tabs=1, tab=30 mm,
                                    screw=0, rotation=90 deg, cx=-140 mm, cy=27 mm)
        right_mortise = tab_and_slot(part="slot", length=66 mm, thickness=T, tabs=1, tab=30 mm,
                                     screw=0, rotation=90 deg, cx=140 mm, cy=27 mm)
        drawing sizes {
            for i in range(8) {
                t = Text(SIZES[i], position=(-3.5 * PITCH + i * PITCH, 16), size=7, valign="middle")
            }
        }
        Fillet(body.top_left, 5)
        Fillet(body.top_right, 5)
    }

    left_bracket = bracket()
    right_bracket = bracket()

    # 3D: the back on the wall (its front face at y = 0), the shelf's underside 34 mm up,
    # the brackets standing in the planes x = -140 and x = 140 (their middles)
    Place(back, rotation=(90 deg, 0, 0), position=(0, 0, 0))
    Place(shelf, position=(0, 0, 34))
    Place(left_bracket, rotation=(90 deg, 0, 90 deg), position=(-143, 0, 0))
    Place(right_bracket, rotation=(90 deg, 0, 90 deg), position=(137, 0, 0))

    # on the sheet
    Above(shelf, back, gap=10)
    AlignCenterX(shelf, back)
    RightOf(left_bracket, back, gap=10)
    AlignBottom(left_bracket, back)
    RightOf(right_bracket, left_bracket, gap=10)
    AlignBottom(right_bracket, back)

    # the request's numbers
    assert len(shelf.spanner.u) == 8, "eight spanner slots"
    assert back.body.bb.width == 320 mm and back.body.bb.height == 140 mm, "back 320 x 140"
    assert shelf.body.bb.width == 320 mm, "shelf 320 long"
    assert shelf.body.bb.height - T == 70 mm, "shelf sticks out 70 mm"
    assert shelf.body.bb.top - shelf.spanner.u[0].bb.bottom == 40 mm, "slots 40 deep"
    assert shelf.spanner.u[1].center.x - shelf.spanner.u[0].center.x == 34 mm, "slots 34 apart"
    assert shelf.spanner.u[7].width == 23 mm and shelf.spanner.u[0].width == 11 mm, "widths"
    assert left_bracket.body.bb.width - T == 60 mm, "bracket 60 out"
}
