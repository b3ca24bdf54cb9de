# Request (workshop): a wall rack for three caulking guns, cut from 6 mm plywood.
# - Back plate 360 x 140 mm, corners R6, screwed to the wall with four M4 countersunk
#   screws (heads 8.5 mm), 120 mm either side of the centre, 55 mm above and below it.
# - A shelf 360 mm wide standing out 90 mm from the wall face of the back plate, its top
#   30 mm below the plate's top; it is tenoned into the back plate with three 30 mm tabs.
# - Three slots in the shelf's front edge, 14 mm wide and 55 mm deep, 110 mm apart
#   (centre one in the middle): the plunger rod drops in, the rod's hook rests on the
#   shelf and the gun hangs below. Engraved labels behind the slots: SILICONE, ACRYLIC, GLUE.
# - Two brackets under the shelf, 80 x 80 mm, 160 mm either side of the centre, each with
#   two 20 mm tabs into the back plate and two into the shelf (0.2 mm clearance in slots).
# - "SEALANTS" engraved filled (bold sans, 14 mm) on the back plate above the shelf.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm

labels = ["SILICONE", "ACRYLIC", "GLUE"]

def bracket() -> solid {
    # x: away from the wall (x = 0 is the back plate's front face), y: up (y = 0 is the
    # shelf's underside); tab tips at x = -6 and y = +6
    body = Polygon([(-6, -80), (-6, 0), (0, 0), (0, 6), (80, 6), (80, -14), (16, -80)])
    wall_tabs = tab_and_slot(part="tab", length=80 mm, thickness=6 mm, tabs=2, tab=20 mm,
                             screw=0, rotation=90 deg, cx=-6 mm, cy=-40 mm)
    shelf_tabs = tab_and_slot(part="tab", length=80 mm, thickness=6 mm, tabs=2, tab=20 mm,
                              screw=0, cx=40 mm, cy=6 mm)
}

assembly rack {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=360, height=140, corner_radius=6)
        # the shelf's middle stands at y = 37 (its top at 40, 30 below the top edge)
        shelf_mortise = tab_and_slot(part="slot", length=360 mm, thickness=6 mm, tabs=3,
                                     tab=30 mm, screw=0, clearance=0.2 mm, cx=0 mm, cy=37 mm)
        left_mortise = tab_and_slot(part="slot", length=80 mm, thickness=6 mm, tabs=2,
                                    tab=20 mm, screw=0, clearance=0.2 mm, rotation=90 deg,
                                    cx=-160 mm, cy=-6 mm)
        right_mortise = tab_and_slot(part="slot", length=80 mm, thickness=6 mm, tabs=2,
                                     tab=20 mm, screw=0, clearance=0.2 mm, rotation=90 deg,
                                     cx=160 mm, cy=-6 mm)
        s1 = clearance_hole(size=4, cx=-120 mm, cy=55 mm)
        s2 = clearance_hole(size=4, cx=120 mm, cy=55 mm)
        s3 = clearance_hole(size=4, cx=-120 mm, cy=-55 mm)
        s4 = clearance_hole(size=4, cx=120 mm, cy=-55 mm)
        Countersink([s1, s2, s3, s4], diameter=8.5 mm)
        drawing title {
            t = Text("SEALANTS", position=(0, 55), size=14, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    solid shelf {
        # 90 mm deep plus the 6 mm tabs that go through the back plate (tips at y = 48)
        body = Rectangle(center=(0, 0), width=360, height=96)
        back_tabs = tab_and_slot(part="tab", length=360 mm, thickness=6 mm, tabs=3, tab=30 mm,
                                 screw=0, cx=0 mm, cy=48 mm)
        hole rods {
            for i in range(3) {
                r = Slot(start=(-110 + i * 110, -58), end=(-110 + i * 110, 0), width=14)
            }
        }
        left_mortise = tab_and_slot(part="slot", length=80 mm, thickness=6 mm, tabs=2,
                                    tab=20 mm, screw=0, clearance=0.2 mm, rotation=90 deg,
                                    cx=-160 mm, cy=2 mm)
        right_mortise = tab_and_slot(part="slot", length=80 mm, thickness=6 mm, tabs=2,
                                     tab=20 mm, screw=0, clearance=0.2 mm, rotation=90 deg,
                                     cx=160 mm, cy=2 mm)
        drawing names {
            for i in range(3) {
                t = Text(labels[i], position=(-110 + i * 110, 22), size=6, valign="middle")
            }
        }
    }

    bracket_l = bracket()
    bracket_r = bracket()

    # flat on the sheet: shelf under the back plate, the brackets under the shelf
    Below(shelf, back, gap=10)
    AlignCenterX(shelf, back)
    Below(bracket_l, shelf, gap=10)
    AlignLeft(bracket_l, shelf)
    RightOf(bracket_r, bracket_l, gap=10)
    AlignTop(bracket_r, bracket_l)

    # in 3D: wall at y = +6, back plate's front face at y = 0, z up
    Place(back, position=(0, 6, 0), face="front", up="up")
    Place(shelf, position=(0, -42, 34), face="up", up="back")
    Place(bracket_l, position=(-157, 0, 34), face="left", up="up")
    Place(bracket_r, position=(163, 0, 34), face="left", up="up")

    assert back.body.bb.width == 360 mm and back.body.bb.height == 140 mm, "back plate 360 x 140"
    assert shelf.body.bb.height - 6 mm == 90 mm, "shelf stands out 90 mm from the wall face"
    assert back.body.bb.top - (back.shelf_mortise.slot[0].bb.center_y + 3 mm) == 30 mm,
        "shelf top 30 mm below the plate's top"
    assert len(shelf.rods.r) == 3, "three guns"
    assert shelf.rods.r[1].center.x - shelf.rods.r[0].center.x == 110 mm, "110 mm apart"
    assert shelf.rods.r[0].width == 14 mm, "slots 14 mm wide"
    assert shelf.rods.r[0].bb.top - shelf.body.bb.bottom == 55 mm, "slots 55 mm deep"
    assert back.s2.c.center.x - back.s1.c.center.x == 240 mm, "screws 120 either side"
    assert back.s1.c.center.y - back.s3.c.center.y == 110 mm, "screws 55 above and below"
}
