# Request: a desktop frame for A4 suspension (hanging) files, 6 mm plywood. Two end panels,
# trapezoids 400 mm wide at the foot, 370 at the top, 260 tall, corners rounded 8 mm, each
# with a 100 x 30 mm hand slot 35 mm below its top, a 260 x 100 mm window (r15) to save
# weight, and a label engraved 12 mm tall between them ("A - M" front, "N - Z" back, read
# from outside). Two rails, 25 mm tall, on which the files' hooks hang: their centres 335 mm
# apart, their tops 10 mm below the panels' tops, 300 mm clear between the end panels, each
# ending in a single 15 mm through-tenon glued into each end panel. A 60 mm tall stretcher
# down the middle at the foot keeps the frame square, with two 15 mm tenons at each end.
# FIX after the first valid program: A4 suspension files hang about 240 mm below the rails'
# tops, so a stretcher down the middle would lift them off the rails: two 40 mm stretchers
# outside the files' pockets (centres 180 mm either side of the middle) instead.

units mm
thickness 6 mm

import "std/joints.aidl"

T = 6 mm
SPAN = 300 mm           # clear between the end panels
RAIL_C = 335 mm         # rail centre to centre
RAIL_H = 25 mm
PANEL_H = 260 mm
RAIL_TOP = PANEL_H - 10 mm
STR_H = 40 mm
STR_X = 180 mm          # the stretchers' centres from the middle (FIX)

def end_panel(label="A - M") -> solid {
    body = Trapezoid(center=(0, PANEL_H / 2), bottom_width=400, top_width=370, height=PANEL_H)
    hole hand { s = Slot(center=(0, PANEL_H - 35 mm), length=100, width=30) }
    hole window {
        w = RoundedRectangle(center=(0, 130), width=260, height=100, corner_radius=15)
    }
    left_mortise = tab_and_slot(part="slot", length=RAIL_H, thickness=T, tabs=1, tab=15 mm,
                                screw=0, clearance=0.1 mm, rotation=90 deg,
                                cx=-RAIL_C / 2, cy=RAIL_TOP - RAIL_H / 2)
    right_mortise = tab_and_slot(part="slot", length=RAIL_H, thickness=T, tabs=1, tab=15 mm,
                                 screw=0, clearance=0.1 mm, rotation=90 deg,
                                 cx=RAIL_C / 2, cy=RAIL_TOP - RAIL_H / 2)
    left_foot_mortise = tab_and_slot(part="slot", length=STR_H, thickness=T, tabs=1,
                                     tab=15 mm, screw=0, clearance=0.1 mm, rotation=90 deg,
                                     cx=-STR_X, cy=STR_H / 2)
    right_foot_mortise = tab_and_slot(part="slot", length=STR_H, thickness=T, tabs=1,
                                      tab=15 mm, screw=0, clearance=0.1 mm, rotation=90 deg,
                                      cx=STR_X, cy=STR_H / 2)
    drawing name {
        t = Text(label, position=(0, 195), size=12, font="sans:Bold", valign="middle",
                 fill=true)
    }
    Fillet(body, 8)
}

# a bar between the end panels: x along the frame's depth, y up; tenons at both ends
def bar(h=25 mm, y0=0 mm, tabs=1) -> solid {
    body = Rectangle(center=(SPAN / 2, y0 + h / 2), width=SPAN + 2 * T, height=h)
    front_tenon = tab_and_slot(part="tab", length=h, thickness=T, tabs=tabs, tab=15 mm,
                               screw=0, rotation=90 deg, cx=-T, cy=y0 + h / 2)
    back_tenon = tab_and_slot(part="tab", length=h, thickness=T, tabs=tabs, tab=15 mm,
                              screw=0, rotation=-90 deg, cx=SPAN + T, cy=y0 + h / 2)
}

assembly file_frame {
    front = end_panel(label="A - M")
    back = end_panel(label="N - Z")
    left_rail = bar(h=RAIL_H, y0=RAIL_TOP - RAIL_H, tabs=1)
    right_rail = bar(h=RAIL_H, y0=RAIL_TOP - RAIL_H, tabs=1)
    left_stretcher = bar(h=STR_H, y0=0 mm, tabs=1)
    right_stretcher = bar(h=STR_H, y0=0 mm, tabs=1)

    # 3D: x across, y the depth (front panel's outer face at y = -6), z up
    Place(front, rotation=(90 deg, 0, 0), position=(0, 0, 0))
    Place(back, rotation=(90 deg, 0, 180 deg), position=(0, SPAN, 0))
    Place(left_rail, rotation=(90 deg, 0, 90 deg), position=(-RAIL_C / 2 - T / 2, 0, 0))
    Place(right_rail, rotation=(90 deg, 0, 90 deg), position=(RAIL_C / 2 - T / 2, 0, 0))
    Place(left_stretcher, rotation=(90 deg, 0, 90 deg), position=(-STR_X - T / 2, 0, 0))
    Place(right_stretcher, rotation=(90 deg, 0, 90 deg), position=(STR_X - T / 2, 0, 0))

    # the sheet
    RightOf(back, front, gap=10)
    Below(left_rail, front, gap=10)
    Below(right_rail, left_rail, gap=10)
    Below(left_stretcher, right_rail, gap=10)
    Below(right_stretcher, left_stretcher, gap=10)
    AlignLeft(left_rail, front.window)
    AlignLeft(right_rail, left_rail)
    AlignLeft(left_stretcher, left_rail)
    AlignLeft(right_stretcher, left_rail)

    # the request's numbers
    assert front.body.bottom.length == 400 mm and front.body.height == 260 mm, "end panel 400 x 260"
    assert left_rail.body.bb.width - 2 * T == 300 mm, "300 mm clear between the end panels"
    assert front.right_mortise.slot[0].bb.center_x - front.left_mortise.slot[0].bb.center_x == 335 mm,
        "rail centres 335 apart"
    assert front.body.bb.top - front.left_mortise.slot[0].bb.top >= 10 mm - 0.1 mm,
        "rail tops 10 below the panel top"
    assert front.body.bb.top - front.hand.s.bb.center_y == 35 mm, "hand slot 35 below the top"
    assert left_stretcher.body.bb.height == 40 mm, "stretchers 40 tall"
    assert (front.right_foot_mortise.slot[0].bb.center_x - front.left_foot_mortise.slot[0].bb.center_x
            == 360 mm), "stretchers 180 either side of the middle"
}
