# Request (workshop): "A wall rack for my shop vacuum's attachments, cut from 6 mm ply.
# A back plate 320 x 170 mm hung on two 4 mm screws through keyholes near the top.
# A shelf 320 mm wide that stands out 100 mm from the back, glued into the back with
# 3 tabs 40 mm wide. In the shelf: three round holes 38 mm across for the 35 mm
# tools (brush, round nozzle, floor tool) on 50 mm centres, and a 20 x 60 mm slot for
# the crevice tool, each with its name engraved in front of it. Two right-angle
# brackets under the shelf, 55 mm tall on the back and 80 mm deep under the shelf,
# 120 mm either side of the middle, each glued with one tab into the back and one
# into the shelf. The shelf sits 20 mm below the back's middle."

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

T = 6 mm
back_w = 320 mm
back_h = 170 mm
shelf_d = 100 mm
shelf_y = -20 mm          # shelf's mid-thickness line on the back, from the back's middle
bracket_x = 120 mm
br_h = 55 mm
br_d = 80 mm

def bracket() -> solid {
    # laid flat: the back face is the line x = 0, the shelf's underside the line y = 0
    web = Polygon([(0, 0), (80, 0), (0, -55)])
    top_strip = Rectangle(bottom_left=(0, 0), width=80, height=6)
    back_strip = Rectangle(bottom_left=(-6, -55), width=6, height=55)
    top_tab = tab_and_slot(part="tab", length=80 mm, thickness=6 mm, tabs=1, tab=30 mm,
                           screw=0, cx=40 mm, cy=6 mm)
    back_tab = tab_and_slot(part="tab", length=55 mm, thickness=6 mm, tabs=1, tab=20 mm,
                            screw=0, rotation=90 deg, cx=-6 mm, cy=-27.5 mm)
}

assembly rack {
    solid back {
        body = Rectangle(center=(0, 0), width=back_w, height=back_h)
        shelf_slots = tab_and_slot(part="slot", length=back_w, thickness=T, tabs=3, tab=40 mm,
                                   screw=0, cx=0 mm, cy=shelf_y)
        # the brackets' back edges run from the shelf's underside down br_h
        br_slot_l = tab_and_slot(part="slot", length=br_h, thickness=T, tabs=1, tab=20 mm,
                                 screw=0, rotation=90 deg, cx=-bracket_x,
                                 cy=shelf_y - T / 2 - br_h / 2)
        br_slot_r = tab_and_slot(part="slot", length=br_h, thickness=T, tabs=1, tab=20 mm,
                                 screw=0, rotation=90 deg, cx=bracket_x,
                                 cy=shelf_y - T / 2 - br_h / 2)
        hang_l = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, cx=-110 mm, cy=55 mm)
        hang_r = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, cx=110 mm, cy=55 mm)
    }

    solid shelf {
        # front edge at y = -50, back face of the back plate at y = 50, tabs' tips at 56
        body = Rectangle(bottom_left=(-160, -50), width=320, height=106)
        tabs = tab_and_slot(part="tab", length=back_w, thickness=T, tabs=3, tab=40 mm,
                            screw=0, cx=0 mm, cy=56 mm)
        br_l = tab_and_slot(part="slot", length=br_d, thickness=T, tabs=1, tab=30 mm,
                            screw=0, rotation=90 deg, cx=-bracket_x, cy=50 mm - br_d / 2)
        br_r = tab_and_slot(part="slot", length=br_d, thickness=T, tabs=1, tab=30 mm,
                            screw=0, rotation=90 deg, cx=bracket_x, cy=50 mm - br_d / 2)
        hole tools {
            for i in range(3) {
                c = Circle(center=(-75 + i * 50, 5), diameter=38)
            }
            crevice = Slot(center=(85, 10), length=60, width=20, rotation=90)
        }
        drawing labels {
            names = ["BRUSH", "ROUND", "FLOOR"]
            for i in range(3) {
                t = Text(names[i], position=(-75 + i * 50, -38), size=6)
            }
            c = Text("CREVICE", position=(85, -38), size=6)
        }
    }

    left_bracket = bracket()
    right_bracket = bracket()

    Below(shelf, back, gap=15)
    AlignCenterX(shelf, back)
    RightOf(left_bracket, back, gap=15)
    AlignTop(left_bracket, back)
    RightOf(right_bracket, back, gap=15)
    Below(right_bracket, left_bracket, gap=15)

    assert back.body.bb.width == 320 mm, "back 320 wide"
    assert back.body.bb.height == 170 mm, "back 170 tall"
    assert shelf.body.bb.width == 320 mm, "shelf 320 wide"
    assert shelf.body.bb.height - 6 mm == 100 mm, "shelf stands out 100 mm (tabs through the 6 mm back)"
    assert len(shelf.tools.c) == 3, "three round tool holes"
    assert shelf.tools.c[0].diameter == 38 mm, "38 mm holes"
    assert shelf.tools.c[1].center.x - shelf.tools.c[0].center.x == 50 mm, "50 mm centres"
    assert shelf.tools.crevice.width == 20 mm and shelf.tools.crevice.length == 60 mm, "crevice slot 20 x 60"
    assert left_bracket.web.bb.height == 55 mm and left_bracket.web.bb.width == 80 mm, "bracket 55 x 80"
    assert back.br_slot_r.slot[0].bb.center_x - back.body.bb.center_x == 120 mm, "brackets 120 from the middle"
    assert back.body.bb.center_y - back.shelf_slots.slot[0].bb.center_y == 20 mm, "shelf 20 below the middle"
}
