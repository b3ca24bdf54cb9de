# Request (kitchen): a wall rack for a stand mixer's three tools (whisk, flat beater,
# dough hook), 6 mm birch ply, glued.
# Back plate 320 x 140 mm, 6 mm corner radii, two 4 mm wall screws (countersunk, 9 mm
# heads) 100 mm apart, 90 mm below the top edge. A shelf 320 x 110 mm whose top face is
# 30 mm below the back's top edge, joined to the back by 3 tabs 30 mm wide. Three hanging
# notches in the shelf, 100 mm apart (the middle one centred), 14 mm wide, running 70 mm
# in from the front edge with a round end, their mouths rounded 3 mm. Labels WHISK,
# BEATER, HOOK (10 mm, sans bold, filled) on the back above each notch, 15 mm below the top.
# Two brackets under the shelf, 100 mm along the shelf and 100 mm down the back, their
# middle planes 20 mm in from the shelf's ends, each with 2 tabs (20 mm) into the shelf
# and 2 into the back; the bracket's long edge cut off 12 mm from each point.

units mm
thickness 6 mm

import "std/fasteners.aidl"
import "std/joints.aidl"

t = 6 mm
W = 320 mm
back_h = 140 mm
shelf_d = 110 mm
shelf_drop = 30 mm        # back top to shelf top face
pitch = 100 mm
notch_w = 14 mm
notch_depth = 70 mm
arm = 100 mm              # bracket legs
bracket_in = 20 mm
names = ["WHISK", "BEATER", "HOOK"]

shelf_mid_y = back_h / 2 - shelf_drop - t / 2      # in the back's frame
shelf_under_y = back_h / 2 - shelf_drop - t
bx = W / 2 - bracket_in

def bracket() -> solid {
    web = Polygon([(0, 0), (arm, 0), (arm, -12), (12, -arm), (0, -arm)])
    top_blank = Rectangle(bottom_left=(0, 0), width=arm, height=t)
    back_blank = Rectangle(bottom_left=(-t, -arm), width=t, height=arm)
    top_tabs = tab_and_slot(part="tab", length=arm, thickness=t, tabs=2, tab=20 mm, screw=0,
                            cx=arm / 2, cy=t)
    back_tabs = tab_and_slot(part="tab", length=arm, thickness=t, tabs=2, tab=20 mm, screw=0,
                             rotation=90 deg, cx=-t, cy=-arm / 2)
}

assembly mixer_rack {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=W, height=back_h, corner_radius=6)
        shelf_slots = tab_and_slot(part="slot", length=W, thickness=t, tabs=3, tab=30 mm, screw=0,
                                   cx=0, cy=shelf_mid_y)
        left_slots = tab_and_slot(part="slot", length=arm, thickness=t, tabs=2, tab=20 mm, screw=0,
                                  rotation=90 deg, cx=-bx, cy=shelf_under_y - arm / 2)
        right_slots = tab_and_slot(part="slot", length=arm, thickness=t, tabs=2, tab=20 mm, screw=0,
                                   rotation=90 deg, cx=bx, cy=shelf_under_y - arm / 2)
        wl = clearance_hole(size=4, cx=-50, cy=back_h / 2 - 90)
        wr = clearance_hole(size=4, cx=50, cy=back_h / 2 - 90)
        Countersink([wl, wr], diameter=9 mm)
        drawing labels {
            for i in range(3) {
                n = Text(names[i], position=((i - 1) * pitch, back_h / 2 - 15), size=10,
                         font="sans:Bold", valign="middle", fill=true)
            }
        }
    }

    solid shelf {
        # drawn from above: +y is the back edge (y = shelf_d / 2), tabs beyond it
        body = Rectangle(center=(0, 0), width=W, height=shelf_d)
        tab_blank = Rectangle(bottom_left=(-W / 2, shelf_d / 2), width=W, height=t)
        back_tabs = tab_and_slot(part="tab", length=W, thickness=t, tabs=3, tab=30 mm, screw=0,
                                 cx=0, cy=shelf_d / 2 + t)
        left_slots = tab_and_slot(part="slot", length=arm, thickness=t, tabs=2, tab=20 mm, screw=0,
                                  rotation=90 deg, cx=-bx, cy=shelf_d / 2 - arm / 2)
        right_slots = tab_and_slot(part="slot", length=arm, thickness=t, tabs=2, tab=20 mm, screw=0,
                                   rotation=90 deg, cx=bx, cy=shelf_d / 2 - arm / 2)
        for i in range(3) {
            hole notch {
                mouth = Rectangle(corner=((i - 1) * pitch - notch_w / 2, -shelf_d / 2 - 1),
                                  opposite=((i - 1) * pitch + notch_w / 2,
                                            -shelf_d / 2 + notch_depth - notch_w / 2))
                end = Circle(center=((i - 1) * pitch, -shelf_d / 2 + notch_depth - notch_w / 2),
                             diameter=notch_w)
            }
            Fillet([body, notch.mouth], 3 mm)
        }
    }

    left_bracket = bracket()
    right_bracket = bracket()

    # 3D: the back stands at y = -6..0 facing the front; the shelf lies on its tabs;
    # brackets stand in the planes x = -bx and x = bx
    Place(back, position=(0, 0, 0), face="front", up="up")
    Place(shelf, position=(0, -t - shelf_d / 2, shelf_under_y), face="up", up="back")
    Place(left_bracket, position=(-bx + t / 2, -t, shelf_under_y), face="left", up="up")
    Place(right_bracket, position=(bx + t / 2, -t, shelf_under_y), face="left", up="up")

    # on the sheet
    Below(shelf, back, gap=10)
    AlignLeft(shelf, back)
    RightOf(left_bracket, back, gap=10)
    AlignTop(left_bracket, back)
    RightOf(right_bracket, left_bracket, gap=10)
    AlignTop(right_bracket, back)

    assert back.body.bb.width == 320 mm and back.body.bb.height == 140 mm, "back 320 x 140"
    assert shelf.body.bb.width == 320 mm and shelf.body.bb.height == 110 mm, "shelf 320 x 110"
    assert len(shelf.notch) == 3, "three notches"
    assert abs(shelf.notch[1].end.center.x - shelf.notch[0].end.center.x - 100 mm) < 0.01 mm, "notches 100 apart"
    assert abs(shelf.notch[0].end.center.y + 7 mm - shelf.body.bb.bottom - 70 mm) < 0.01 mm, "notch 70 deep"
    assert shelf.notch[0].end.diameter == 14 mm, "notch 14 wide"
    assert abs(back.wr.c.center.x - back.wl.c.center.x - 100 mm) < 0.01 mm, "wall screws 100 apart"
    assert abs(back.body.bb.top - back.wl.c.center.y - 90 mm) < 0.01 mm, "screws 90 below the top"
    assert abs(back.body.bb.top - back.labels.n[0].position.y - 15 mm) < 0.01 mm, "labels 15 below the top"
    assert abs(back.body.bb.top - (back.shelf_slots.slot[0].bb.top) - 30 mm) < 0.01 mm, "shelf top 30 below the back's top"
    assert abs(back.right_slots.slot[0].bb.center_x - back.body.bb.right - (-20 mm)) < 0.01 mm, "brackets 20 in from the ends"
}
