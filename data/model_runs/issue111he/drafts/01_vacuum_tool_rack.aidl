# Request (home): a wall rack for my vacuum cleaner's attachments, cut from 6 mm plywood.
# A back plate 300 x 160 mm hangs on two screws 240 mm apart through keyholes (head 9 mm,
# shank 4.5 mm, slot 10 mm long, upward). A shelf 300 mm wide and 90 mm deep is glued into
# the back with 3 tabs 40 mm wide; it holds the tools hanging in three cradle holes: two
# round 38 mm holes (dusting brush and sofa tool, tubes 35 mm) and a 60 x 24 mm slot for the
# crevice tool, their centres 50 mm out from the back. Two triangular brackets, legs 78 mm
# along the back and under the shelf, are tabbed (one 30 mm tab each) into the back and the
# shelf at x = +-100 mm. Labels BRUSH, SOFA, CREVICE engraved in front of each hole.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

ply = 6 mm
shelf_y = 40 mm        # the shelf's middle line on the back plate, above its centre
bracket_x = 100 mm
leg = 78 mm

def bracket() -> solid {
    # right angle at (0, 0): top edge (under the shelf) along +x, back edge along -y;
    # the outline reaches one ply past both edges for the tabs
    tri = Polygon([(-6, 6), (84, 6), (-6, -84)])
    top_tab = tab_and_slot(part="tab", length=90 mm, thickness=6 mm, tabs=1, tab=30 mm,
                           screw=0, cx=39 mm, cy=6 mm)
    back_tab = tab_and_slot(part="tab", length=90 mm, thickness=6 mm, tabs=1, tab=30 mm,
                            screw=0, rotation=90 deg, cx=-6 mm, cy=-39 mm)
}

assembly vacuum_rack {
    solid back {
        body = Rectangle(center=(0, 0), width=300, height=160)
        shelf_slots = tab_and_slot(part="slot", length=300 mm, thickness=6 mm, tabs=3,
                                   tab=40 mm, screw=0, cx=0 mm, cy=shelf_y)
        # bracket mortises: the bracket's top edge is the shelf's underside (shelf_y - 3)
        left_mortise = tab_and_slot(part="slot", length=90 mm, thickness=6 mm, tabs=1,
                                    tab=30 mm, screw=0, rotation=90 deg,
                                    cx=-bracket_x, cy=shelf_y - 3 mm - 39 mm)
        right_mortise = tab_and_slot(part="slot", length=90 mm, thickness=6 mm, tabs=1,
                                     tab=30 mm, screw=0, rotation=90 deg,
                                     cx=bracket_x, cy=shelf_y - 3 mm - 39 mm)
        k1 = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg,
                     cx=-120 mm, cy=62 mm)
        k2 = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg,
                     cx=120 mm, cy=62 mm)
        assert body.bb.width == 300 mm and body.bb.height == 160 mm, "back 300 x 160"
        assert k2.head_hole.center.x - k1.head_hole.center.x == 240 mm, "screws 240 apart"
    }

    solid shelf {
        # 90 mm deep from the back plate's face to the front edge, plus the 6 mm tabs
        body = Rectangle(center=(0, 0), width=300, height=96)
        tabs = tab_and_slot(part="tab", length=300 mm, thickness=6 mm, tabs=3, tab=40 mm,
                            screw=0, cx=0 mm, cy=48 mm)
        # the back face line is y = 42; the bracket's tab is centred 39 mm out from it
        left_mortise = tab_and_slot(part="slot", length=90 mm, thickness=6 mm, tabs=1,
                                    tab=30 mm, screw=0, rotation=90 deg,
                                    cx=-bracket_x, cy=3 mm)
        right_mortise = tab_and_slot(part="slot", length=90 mm, thickness=6 mm, tabs=1,
                                     tab=30 mm, screw=0, rotation=90 deg,
                                     cx=bracket_x, cy=3 mm)
        hole cradles {
            brush = Circle(center=(-60, -8), diameter=38)
            sofa = Circle(center=(0, -8), diameter=38)
            crevice = Slot(center=(55, -8), length=60, width=24)
        }
        drawing labels {
            t1 = Text("BRUSH", position=(-60, -38), size=6, valign="middle")
            t2 = Text("SOFA", position=(0, -38), size=6, valign="middle")
            t3 = Text("CREVICE", position=(55, -38), size=6, valign="middle")
        }
        assert body.bb.height - 6 mm == 90 mm, "shelf 90 deep"
        assert 42 mm - cradles.brush.center.y == 50 mm, "holes 50 out from the back"
        assert cradles.brush.diameter == 38 mm and cradles.sofa.diameter == 38 mm, "38 mm holes"
        assert cradles.crevice.length == 60 mm and cradles.crevice.width == 24 mm, "60 x 24 slot"
        assert distance(labels, cradles) >= 3 mm, "labels clear the holes"
    }

    left_bracket = bracket()
    right_bracket = bracket()

    # flat layout for cutting
    Below(shelf, back, gap=10)
    AlignLeft(shelf, back)
    RightOf(left_bracket, back, gap=10)
    AlignTop(left_bracket, back)
    Below(right_bracket, left_bracket, gap=10)
    AlignLeft(right_bracket, left_bracket)
}
