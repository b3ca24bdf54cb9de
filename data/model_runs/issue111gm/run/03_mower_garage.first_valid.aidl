# Request (garden): a garage for a robot lawn mower (65 x 50 x 28 cm), 9 mm exterior ply,
# screwed together with M5 screws into captive nuts (tab-and-slot T-slots).
# Two side panels 560 mm deep, 360 mm high at the front and 300 mm at the back (the roof
# sheds rain backwards), each with a 120 mm porthole centred 280 mm from the back and
# 180 mm up, and 2 tabs 60 mm wide standing up through the roof.
# The sides stand 700 mm apart (inside). A back panel 700 x 300 mm set 20 mm in from the
# sides' back edges, 2 tabs (60 mm) into each side, two rows of 6 vent slots 60 x 10 mm
# (rows 200 and 240 mm up), and a 40 x 25 mm notch at the bottom middle for the
# charging cable. A front header 700 x 80 mm set 20 mm in from the sides' front edges
# with its top 356 mm up, 2 tabs (20 mm) into each side, "ROBBIE" engraved filled (50 mm
# capitals, sans bold). A roof 778 x 620 mm lying on the sides, overhanging them equally
# front and back, 30 mm past each side, with the mortises and screw holes for the tabs.

units mm
thickness 9 mm

import "std/joints.aidl"

t = 9 mm
depth = 560 mm
h_front = 360 mm
h_back = 300 mm
inner_w = 700 mm
inset = 20 mm
slope = atan((h_front - h_back) / depth)
slope_len = sqrt(depth ** 2 + (h_front - h_back) ** 2)
band = t / cos(slope)                 # the tab band above the sloping edge, measured upright
side_x = inner_w / 2 + t / 2          # middle plane of each side
roof_w = inner_w + 2 * t + 2 * 30 mm
roof_d = 620 mm
back_h = 300 mm
header_h = 80 mm
header_top = 356 mm

def side_panel() -> solid {
    body = Polygon([(0, 0), (depth, 0), (depth, h_front + band), (0, h_back + band)])
    roof_tabs = tab_and_slot(part="tab", length=slope_len, thickness=t, tabs=2, tab=60 mm, screw=5,
                             rotation=slope, cx=depth / 2, cy=(h_front + h_back) / 2 + band)
    back_slots = tab_and_slot(part="slot", length=back_h, thickness=t, tabs=2, tab=60 mm, screw=5,
                              rotation=90 deg, cx=inset + t / 2, cy=back_h / 2)
    header_slots = tab_and_slot(part="slot", length=header_h, thickness=t, tabs=2, tab=20 mm, screw=5,
                                rotation=90 deg, cx=depth - inset - t / 2, cy=header_top - header_h / 2)
    hole porthole { c = Circle(center=(depth - 280, 180), diameter=120) }
}

assembly garage {
    left_side = side_panel()
    right_side = side_panel()

    solid back {
        body = Rectangle(bottom_left=(-inner_w / 2 - t, 0), width=inner_w + 2 * t, height=back_h)
        left_tabs = tab_and_slot(part="tab", length=back_h, thickness=t, tabs=2, tab=60 mm, screw=5,
                                 rotation=90 deg, cx=-inner_w / 2 - t, cy=back_h / 2)
        right_tabs = tab_and_slot(part="tab", length=back_h, thickness=t, tabs=2, tab=60 mm, screw=5,
                                  rotation=-90 deg, cx=inner_w / 2 + t, cy=back_h / 2)
        for r in range(2) {
            for c in range(6) {
                hole vent { s = Slot(center=((c - 2.5) * 100, 200 + r * 40), length=60, width=10) }
            }
        }
        hole cable { n = Rectangle(center=(0, 12.5 - 1), width=40, height=25 + 2) }
    }

    solid header {
        body = Rectangle(center=(0, 0), width=inner_w + 2 * t, height=header_h)
        left_tabs = tab_and_slot(part="tab", length=header_h, thickness=t, tabs=2, tab=20 mm, screw=5,
                                 rotation=90 deg, cx=-inner_w / 2 - t, cy=0)
        right_tabs = tab_and_slot(part="tab", length=header_h, thickness=t, tabs=2, tab=20 mm, screw=5,
                                  rotation=-90 deg, cx=inner_w / 2 + t, cy=0)
        drawing name {
            n = Text("ROBBIE", position=(0, 0), size=50, font="sans:Bold", valign="middle", fill=true)
        }
    }

    solid roof {
        # drawn flat: +y runs down the slope to the back eave
        body = Rectangle(center=(0, 0), width=roof_w, height=roof_d)
        left_slots = tab_and_slot(part="slot", length=slope_len, thickness=t, tabs=2, tab=60 mm, screw=5,
                                  rotation=90 deg, cx=-side_x, cy=0)
        right_slots = tab_and_slot(part="slot", length=slope_len, thickness=t, tabs=2, tab=60 mm, screw=5,
                                   rotation=90 deg, cx=side_x, cy=0)
    }

    # 3D: the opening faces the front (-y); the back at y = depth
    Place(left_side, position=(-inner_w / 2, depth, 0), face="left", up="up")
    Place(right_side, position=(inner_w / 2 + t, depth, 0), face="left", up="up")
    Place(back, position=(0, depth - inset, 0), face="front", up="up")
    Place(header, position=(0, inset + t, header_top - header_h / 2), face="front", up="up")
    Place(roof, position=(0, depth / 2, (h_front + h_back) / 2), rotation=(-slope, 0, 0))

    # on the sheet
    RightOf(right_side, left_side, gap=10)
    AlignBottom(right_side, left_side)
    Above(back, left_side, gap=10)
    AlignLeft(back, left_side)
    Above(header, back, gap=10)
    AlignLeft(header, back)
    RightOf(roof, right_side, gap=10)
    AlignBottom(roof, left_side)

    assert abs(left_side.body.points[1].x - left_side.body.points[0].x - 560 mm) < 0.01 mm, "sides 560 deep"
    assert abs(left_side.body.points[2].y - band - 360 mm) < 0.01 mm, "360 high at the front"
    assert abs(left_side.body.points[3].y - band - 300 mm) < 0.01 mm, "300 high at the back"
    assert left_side.porthole.c.diameter == 120 mm, "120 mm porthole"
    assert abs(back.body.bb.width - 2 * t - 700 mm) < 0.01 mm, "700 inside"
    assert sum([len(r) for r in back.vent]) == 12, "12 vent slots"
    assert back.cable.n.width == 40 mm, "cable notch 40 wide"
    assert abs(back.cable.n.bb.top - back.body.bb.bottom - 25 mm) < 0.01 mm, "cable notch 25 high"
    assert header.body.bb.height == 80 mm, "header 80 high"
    assert roof.body.bb.width == 778 mm and roof.body.bb.height == 620 mm, "roof 778 x 620"
    assert abs((roof_w - inner_w - 2 * t) / 2 - 30 mm) < 0.01 mm, "30 mm overhang at the sides"
    assert roof_d > slope_len, "the roof overhangs front and back"
}
