# Request: a fridge can dispenser for 330 ml cans (66 mm across, 115 mm long), 3 mm birch ply.
# - Two sides 320 mm deep x 200 mm tall, top corners rounded R30, "COLD DRINKS" engraved 14 mm
#   high on the outside of each, centred 160 mm from the front, baseline 165 mm up.
# - 120 mm inside width between the sides.
# - Lower ramp from 15 to 305 mm behind the front edge, rising 5 deg towards the back, its
#   mid-plane 20 mm up at the front end: cans roll forward on it to the front stop.
# - Upper ramp from 15 to 230 mm behind the front, falling 5 deg towards the back, its
#   mid-plane 115 mm up at the back end: cans loaded at the front roll back and drop 80 mm
#   (between its back end and the back panel) onto the lower ramp.
# - Front stop 30 mm tall (10 to 40 mm up), its middle 8.5 mm behind the front edge;
#   back panel 170 mm tall (20 to 190 mm up), its middle 311.5 mm behind the front edge.
# - Every cross piece glued with tabs through slots in the sides: 3 tabs of 30 mm on each ramp
#   edge, 3 of 25 mm on the back panel, one 15 mm tenon on each end of the stop.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
inside = 120 mm
slope = 5 deg
side_d = 320 mm
side_h = 200 mm
lo_x0 = 15 mm
lo_x1 = 305 mm
lo_y0 = 20 mm
lo_y1 = lo_y0 + (lo_x1 - lo_x0) * tan(slope)
lo_len = (lo_x1 - lo_x0) / cos(slope)
up_x0 = 15 mm
up_x1 = 230 mm
up_y1 = 115 mm
up_y0 = up_y1 + (up_x1 - up_x0) * tan(slope)
up_len = (up_x1 - up_x0) / cos(slope)
stop_x = 8.5 mm
stop_y0 = 10 mm
stop_y1 = 40 mm
back_x = 311.5 mm
back_y0 = 20 mm
back_y1 = 190 mm

# one side, drawn with x measured from the front edge; s = -1 draws the mirror image (the
# left side, whose outside faces the other way) so the engraving reads on both outsides
def side(s=1) -> solid {
    body = RoundedRectangle(center=(s * side_d / 2, side_h / 2), width=side_d, height=side_h,
                            corner_radii=[30 mm, 30 mm, 0 mm, 0 mm])
    lower = tab_and_slot(part="slot", length=lo_len, thickness=t, tabs=3, tab=30 mm, screw=0,
                         rotation=s * slope, cx=s * (lo_x0 + lo_x1) / 2, cy=(lo_y0 + lo_y1) / 2)
    upper = tab_and_slot(part="slot", length=up_len, thickness=t, tabs=3, tab=30 mm, screw=0,
                         rotation=-s * slope, cx=s * (up_x0 + up_x1) / 2, cy=(up_y0 + up_y1) / 2)
    stop = tab_and_slot(part="slot", length=stop_y1 - stop_y0, thickness=t, tabs=1, tab=15 mm,
                        screw=0, rotation=90 deg, cx=s * stop_x, cy=(stop_y0 + stop_y1) / 2)
    back = tab_and_slot(part="slot", length=back_y1 - back_y0, thickness=t, tabs=3, tab=25 mm,
                        screw=0, rotation=90 deg, cx=s * back_x, cy=(back_y0 + back_y1) / 2)
    Fixed(body)
    drawing label {
        w = Text("COLD DRINKS", position=(s * 160 mm, 165 mm), size=14 mm)
    }
}

# a cross piece: `w` across between the sides' outer faces (tabs through them), `l` long;
# tabs on its left and right edges
def cross(l=100 mm, tabs=3, tab=30 mm) -> solid {
    body = Rectangle(center=(0, 0), width=inside + 2 * t, height=l)
    right = tab_and_slot(part="tab", length=l, thickness=t, tabs=tabs, tab=tab, screw=0,
                         rotation=-90 deg, cx=(inside + 2 * t) / 2, cy=0 mm)
    left = tab_and_slot(part="tab", length=l, thickness=t, tabs=tabs, tab=tab, screw=0,
                        rotation=90 deg, cx=-(inside + 2 * t) / 2, cy=0 mm)
    Fixed(body)
}

assembly dispenser {
    right_side = side(s=1)
    left_side = side(s=-1)
    lower_ramp = cross(l=lo_len, tabs=3, tab=30 mm)
    upper_ramp = cross(l=up_len, tabs=3, tab=30 mm)
    back_panel = cross(l=back_y1 - back_y0, tabs=3, tab=25 mm)
    front_stop = cross(l=stop_y1 - stop_y0, tabs=1, tab=15 mm)

    # on the sheet
    RightOf(right_side, left_side, gap=6)
    Below(lower_ramp, left_side, gap=6)
    AlignLeft(lower_ramp, left_side)
    RightOf(upper_ramp, lower_ramp, gap=6)
    AlignTop(upper_ramp, lower_ramp)
    RightOf(back_panel, upper_ramp, gap=6)
    AlignTop(back_panel, upper_ramp)
    RightOf(front_stop, back_panel, gap=6)
    AlignTop(front_stop, back_panel)

    # in 3D: X across (sides' inner faces at -60 and +60), Y from the front edge backwards, Z up
    Place(right_side, position=(inside / 2, 0, 0), face="right", up="up")
    Place(left_side, position=(-inside / 2, 0, 0), face="left", up="up")
    # ramps: their y along the depth, tilted about X; position = mid-plane centre - t/2 along the normal
    Place(lower_ramp, rotation=(slope, 0, 0),
          position=(0, (lo_x0 + lo_x1) / 2 + t / 2 * sin(slope), (lo_y0 + lo_y1) / 2 - t / 2 * cos(slope)))
    Place(upper_ramp, rotation=(-slope, 0, 0),
          position=(0, (up_x0 + up_x1) / 2 - t / 2 * sin(slope), (up_y0 + up_y1) / 2 - t / 2 * cos(slope)))
    Place(front_stop, position=(0, stop_x + t / 2, (stop_y0 + stop_y1) / 2), face="front", up="up")
    Place(back_panel, position=(0, back_x - t / 2, (back_y0 + back_y1) / 2), face="back", up="up")

    # the request's numbers
    assert right_side.body.bb.width == 320 mm and right_side.body.bb.height == 200 mm, "sides 320 x 200"
    assert lower_ramp.body.bb.width - 2 * 3 mm == 120 mm, "120 inside"
    assert lo_x1 - lo_x0 == 290 mm and up_x1 - up_x0 == 215 mm, "ramp spans 15-305 and 15-230"
    assert back_x - t / 2 - up_x1 == 80 mm, "80 mm drop at the back"
    assert stop_y1 - stop_y0 == 30 mm and back_y1 - back_y0 == 170 mm, "stop 30, back 170 tall"
    # a 66 mm can must pass under the upper ramp where it ends (with 5 mm to spare)
    assert (up_y1 - t / 2) - (lo_y0 + (up_x1 - lo_x0) * tan(slope) + t / 2) >= 66 mm + 5 mm,
        "can clears the upper ramp"
    # and sit on the upper ramp at the front below the sides' top
    assert up_y0 + t / 2 + 66 mm <= 200 mm, "a can on the upper ramp stays within the sides"
    # the resting can is held by the stop: stop top at least 12 mm above the ramp surface
    assert stop_y1 - (lo_y0 + t / 2) >= 12 mm, "stop holds the can"
    assert len(lower_ramp.right.gap) == 4 and len(back_panel.right.gap) == 4, "3 tabs"
    assert len(front_stop.right.gap) == 2, "one tenon"
}
