# Request: a wall rack for multimeter test leads, 6 mm birch ply.
# Back plate 260 x 100 mm, R4 corners, screwed to the wall by two countersunk M4 screws
# 120 mm apart, 20 mm below the plate's middle; "TEST LEADS" engraved filled, bold, 8 mm,
# at the bottom. A shelf 260 mm long standing out 70 mm from the plate's face, its top
# 12 mm below the plate's top, glued into the plate by two 30 mm tenons; ten slots 5 mm wide
# and 30 mm deep from its front edge at 22 mm pitch (mouths rounded R1.5) take the leads'
# cables, the plugs rest on top; each slot numbered 1-10 behind it (5 mm engraved).
# Two triangular brackets under the shelf, 60 mm high and 55 mm deep, 110 mm either side
# of the middle, each with a 20 mm tenon up into the shelf and one back into the plate.
# Mortises 0.2 mm wider than the tenons.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm
t = 6 mm

param pitch = 22 mm, min = 18 mm, max = 24 mm
slots = 10
slot_w = 5 mm
slot_depth = 30 mm
shelf_len = 260 mm
shelf_out = 70 mm
shelf_z = 32 mm          # the shelf's underside on the back plate (plate's y)
bracket_x = 110 mm
br_h = 60 mm
br_d = 55 mm

def slot_x(i) = (i - (slots - 1) / 2) * pitch

def bracket() -> solid {
    body = Polygon([(-t, t), (br_d, t), (br_d, 0), (0, -br_h), (-t, -br_h)])
    # a tenon up into the shelf (tips at the shelf's top) and one back into the plate
    up = tab_and_slot(part="tab", length=br_d + t, thickness=t, tabs=1, tab=20, screw=0,
                      cx=(br_d - t) / 2, cy=t)
    back = tab_and_slot(part="tab", length=br_h + t, thickness=t, tabs=1, tab=20, screw=0,
                        rotation=90, cx=-t, cy=(t - br_h) / 2)
}

assembly rack {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=shelf_len, height=100, corner_radius=4)
        shelf_mortise = tab_and_slot(part="slot", length=shelf_len, thickness=t, tabs=2, tab=30,
                                     screw=0, clearance=0.2, cx=0, cy=shelf_z + t / 2)
        m_left = tab_and_slot(part="slot", length=br_h + t, thickness=t, tabs=1, tab=20, screw=0,
                              clearance=0.2, rotation=90, cx=-bracket_x,
                              cy=shelf_z + (t - br_h) / 2)
        m_right = tab_and_slot(part="slot", length=br_h + t, thickness=t, tabs=1, tab=20, screw=0,
                               clearance=0.2, rotation=90, cx=bracket_x,
                               cy=shelf_z + (t - br_h) / 2)
        screw_l = clearance_hole(size=4, cx=-60, cy=-20)
        screw_r = clearance_hole(size=4, cx=60, cy=-20)
        Countersink([screw_l, screw_r], diameter=9)
        drawing title {
            word = Text("TEST LEADS", position=(0, -38), size=8, font="sans:Bold", fill=true,
                        valign="middle")
        }
    }

    solid shelf {
        # tenon tips on y = 0 (the wall side of the back plate), the front edge at -(70 + 6)
        panel = Rectangle(center=(0, -(shelf_out + t) / 2), width=shelf_len, height=shelf_out + t)
        tenons = tab_and_slot(part="tab", length=shelf_len, thickness=t, tabs=2, tab=30, screw=0,
                              cx=0, cy=0)
        hole leads {
            for i in range(slots) {
                s = Slot(start=(slot_x(i), -(shelf_out + t) - 4),
                         end=(slot_x(i), -(shelf_out + t) + slot_depth - slot_w / 2), width=slot_w)
            }
        }
        m_left = tab_and_slot(part="slot", length=br_d + t, thickness=t, tabs=1, tab=20, screw=0,
                              clearance=0.2, rotation=90, cx=-bracket_x, cy=-t - (br_d - t) / 2)
        m_right = tab_and_slot(part="slot", length=br_d + t, thickness=t, tabs=1, tab=20, screw=0,
                               clearance=0.2, rotation=90, cx=bracket_x, cy=-t - (br_d - t) / 2)
        drawing numbers {
            for i in range(slots) {
                n = Text(str(i + 1), position=(slot_x(i), -(shelf_out + t) + slot_depth + 8), size=5,
                         valign="middle")
            }
        }
        Fillet([[panel.bottom, leads.s[i]] for i in range(slots)], 1.5)
    }

    b_left = bracket()
    b_right = bracket()

    # on the sheet
    Below(shelf, back, gap=6)
    AlignLeft(shelf, back)
    RightOf(b_left, back, gap=6)
    AlignTop(b_left, back)
    Below(b_right, b_left, gap=6)
    AlignLeft(b_right, b_left)

    # in 3D: the plate's face to the front, the shelf flat, the brackets upright under it
    Place(back, position=(0, 0, 0), face="front")
    Place(shelf, position=(0, 0, shelf_z), face="up")
    Place(b_left, position=(-bracket_x + t / 2, -t, shelf_z), face="left", up="up")
    Place(b_right, position=(bracket_x + t / 2, -t, shelf_z), face="left", up="up")

    # the request's numbers
    assert back.body.width == 260 mm and back.body.height == 100 mm, "plate 260 x 100"
    assert back.screw_r.c.center.x - back.screw_l.c.center.x == 120 mm, "screws 120 apart"
    assert back.body.center.y - back.screw_l.c.center.y == 20 mm, "screws 20 below the middle"
    assert back.body.bb.top - (shelf_z + t) == 12 mm, "shelf top 12 below the plate top"
    assert shelf.panel.height - t == 70 mm, "shelf stands out 70"
    assert len(shelf.leads.s) == 10, "ten slots"
    assert shelf.leads.s[1].center.x - shelf.leads.s[0].center.x == 22 mm, "22 mm pitch"
    assert shelf.leads.s[0].width == 5 mm, "slots 5 wide"
    assert shelf.leads.s[0].end.y + slot_w / 2 - shelf.panel.bb.bottom == 30 mm, "slots 30 deep"
    assert distance(shelf.leads, shelf.m_left) >= 3 mm, "slots clear of the bracket mortises"
    assert distance(back.title, back.screw_l) >= 3 mm, "title clear of the screws"
    assert 2 * bracket_x == 220 mm, "brackets 110 either side"
}
