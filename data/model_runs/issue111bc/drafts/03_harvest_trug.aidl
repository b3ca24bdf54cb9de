# Request (garden): "A flat-pack garden trug for picking vegetables, 6 mm exterior ply, glued.
# Two end pieces: a trapezoid 160 mm across the bottom, 240 mm across the top, 120 mm tall,
# with a 40 mm wide post rising from the middle to 260 mm overall, round-topped, holding a
# 25 mm broom-handle dowel (25.3 mm hole, its centre 20 mm below the top) that runs end to end
# as the handle. Two sloping sides and a bottom tab into the ends through mortises (tabs 6 mm
# long, through the 6 mm ends): sides 400 mm long over the tabs (388 mm between the ends), set
# 6 mm in from the ends' sloping edges so the mortises keep a 6 mm wall, two 30 mm tabs each
# side; the bottom 400 mm long over the tabs, 134 mm wide, its underside 9 mm up, two 35 mm
# tabs each end, with 12 drainage slots 30 x 6 mm (2 rows of 6). 'HARVEST' engraved filled
# on one side, 40 mm tall letters."

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
end_bottom = 160 mm
end_top = 240 mm
end_h = 120 mm
post_w = 40 mm
overall_h = 260 mm
dowel_hole = 25.3 mm
inner_len = 388 mm
wall = 6 mm
bottom_w = 134 mm
bottom_z = 9 mm

# the ends' sloping edge: angle from the horizontal and its inward normal (right-hand edge)
slope = atan2(end_h, (end_top - end_bottom) / 2)
nx = -sin(slope)
ny = cos(slope)
# the side's outer face: from the bottom corner moved `wall` inward, up to the ends' top edge
side_x0 = end_bottom / 2 + wall * nx
side_y0 = wall * ny
side_h = (end_h - side_y0) / sin(slope)
# the middle of the side panel's thickness, halfway up: where its mortises are centred
mid_x = side_x0 + side_h / 2 * cos(slope) + t / 2 * nx
mid_y = side_y0 + side_h / 2 * sin(slope) + t / 2 * ny

def trug_end() -> solid {
    tray = Trapezoid(center=(0, end_h / 2), bottom_width=end_bottom, top_width=end_top,
                     height=end_h)
    post = RoundedRectangle(bottom_left=(-post_w / 2, end_h - 10 mm), width=post_w,
                            height=overall_h - end_h + 10 mm,
                            corner_radii=[post_w / 2, post_w / 2, 0, 0])
    hole handle { c = Circle(center=(0, overall_h - 20 mm), diameter=dowel_hole) }
    bottom_slots = tab_and_slot(part="slot", length=bottom_w, thickness=t, tabs=2, tab=35 mm,
                                screw=0, cx=0 mm, cy=bottom_z + t / 2)
    right_slots = tab_and_slot(part="slot", length=side_h, thickness=t, tabs=2, tab=30 mm,
                               screw=0, rotation=slope, cx=mid_x, cy=mid_y)
    left_slots = tab_and_slot(part="slot", length=side_h, thickness=t, tabs=2, tab=30 mm,
                              screw=0, rotation=180 deg - slope, cx=-mid_x, cy=mid_y)
}

def trug_side(label="") -> solid {
    body = Rectangle(center=(0, side_h / 2), width=inner_len + 2 * t, height=side_h)
    left_tabs = tab_and_slot(part="tab", length=side_h, thickness=t, tabs=2, tab=30 mm,
                             screw=0, rotation=90 deg, cx=-(inner_len / 2 + t), cy=side_h / 2)
    right_tabs = tab_and_slot(part="tab", length=side_h, thickness=t, tabs=2, tab=30 mm,
                              screw=0, rotation=-90 deg, cx=inner_len / 2 + t, cy=side_h / 2)
    if label != "" {
        drawing word {
            w = Text(label, position=(0, side_h / 2), size=40, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }
}

def trug_bottom() -> solid {
    body = Rectangle(center=(0, 0), width=inner_len + 2 * t, height=bottom_w)
    left_tabs = tab_and_slot(part="tab", length=bottom_w, thickness=t, tabs=2, tab=35 mm,
                             screw=0, rotation=90 deg, cx=-(inner_len / 2 + t), cy=0 mm)
    right_tabs = tab_and_slot(part="tab", length=bottom_w, thickness=t, tabs=2, tab=35 mm,
                              screw=0, rotation=-90 deg, cx=inner_len / 2 + t, cy=0 mm)
    hole drain { s = Slot(center=(-137.5, -25), length=30, width=6, rotation=90 deg) }
    drains = GridPattern(drain, 2, 6, (55, 50))
}

assembly trug {
    end_a = trug_end()
    end_b = trug_end()
    side_a = trug_side(label="HARVEST")
    side_b = trug_side()
    bottom = trug_bottom()

    # on the sheet
    RightOf(end_b, end_a, gap=10)
    AlignBottom(end_b, end_a)
    Above(side_a, end_a, gap=10)
    AlignLeft(side_a, end_a)
    Above(side_b, side_a, gap=10)
    AlignLeft(side_b, side_a)
    Above(bottom, side_b, gap=10)
    AlignLeft(bottom, side_b)

    # assembled: x along the trug, y across, z up; the ends stand at x = -200 and x = +194
    Place(end_a, rotation=(90 deg, 0, 90 deg), position=(-(inner_len / 2 + t), 0, 0))
    Place(end_b, rotation=(90 deg, 0, 90 deg), position=(inner_len / 2, 0, 0))
    Place(side_a, rotation=(slope, 0, 0), position=(0, side_x0, side_y0))
    Place(side_b, rotation=(slope, 0, 180 deg), position=(0, -side_x0, side_y0))
    Place(bottom, position=(0, 0, bottom_z))

    # the request's numbers
    assert end_a.tray.bottom_width == 160 mm and end_a.tray.top_width == 240 mm, "end sizes"
    assert end_a.tray.height == 120 mm, "120 mm tall"
    assert end_a.post.bb.top - end_a.tray.bb.bottom == 260 mm, "260 mm overall"
    assert end_a.post.bb.top - end_a.handle.c.center.y == 20 mm, "dowel 20 mm below the top"
    assert side_a.body.width == 400 mm and bottom.body.width == 400 mm, "400 over the tabs"
    assert bottom.body.height == 134 mm, "bottom 134 wide"
    assert len(bottom.drains) == 12, "12 drainage slots"
    assert end_a.post.bb.width == 40 mm, "40 mm post"
    # the sides end level with the ends' top edge
    assert abs(side_y0 + side_h * sin(slope) - end_h) < 0.01 mm, "side top level"
    # the bottom clears the sides' inner faces
    assert bottom_w / 2 < (bottom_z - side_y0 - t * ny) / tan(slope) + side_x0 + t * nx,
        "bottom fits between the sides"
}
