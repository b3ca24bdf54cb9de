# Request (workshop): an open tool tote for the garage, cut from 6 mm birch ply.
# The box is 400 mm long, 200 mm wide and 150 mm tall outside, finger-jointed at all
# four corners and into the bottom (fingers about 25 mm). The two end panels rise above
# the sides into a tapered peak 290 mm tall overall, with a 28.5 mm hole whose centre is
# 250 mm above the bottom, for a 28 mm hardwood dowel handle. "WORKSHOP" engraved
# (filled, bold, 30 mm letters) in the middle of the front side.

import "std/joints.aidl"

thickness 6 mm

param L = 400 mm, min = 250 mm, max = 600 mm     # outside length
param W = 200 mm, min = 120 mm, max = 300 mm     # outside width
param H = 150 mm, min = 80 mm, max = 250 mm      # side height
param peak = 290 mm, min = 200 mm, max = 400 mm  # end panels' overall height
param handle_up = 250 mm, min = 150 mm, max = 360 mm  # dowel centre above the bottom
param dowel_hole = 28.5 mm, min = 10 mm, max = 40 mm
t = 6 mm
fw = 25 mm

def end_panel() -> solid {
    p = finger_panel(width=W, height=H, thickness=t, finger=fw,
                     bottom="fingers", right="slots", top="flat", left="slots")
    # the tapered peak above the sides: from the full width down to a round top
    # whose circle is concentric with the dowel hole
    top_r = peak - handle_up
    peak_band = Hull(Rectangle(center=(0, H / 2 + 1), width=W, height=2),
                     Circle(center=(0, -H / 2 + handle_up), radius=top_r))
    hole grip { c = Circle(center=(0, -H / 2 + handle_up), diameter=dowel_hole) }
}

def side_panel() -> solid {
    p = finger_panel(width=L, height=H, thickness=t, finger=fw,
                     bottom="fingers", right="fingers", top="flat", left="fingers")
}

assembly tote {
    bottom = finger_panel(width=L, height=W, thickness=t, finger=fw,
                          bottom="slots", right="slots", top="slots", left="slots")
    front = side_panel()
    back = side_panel()
    end_l = end_panel()
    end_r = end_panel()

    drawing label {
        word = Text("WORKSHOP", position=(0, 0), size=30, font="sans:Bold",
                    valign="middle", fill=true)
    }
    CutInto(label, front)
    At(label.word.position, front.p.outline.center)

    # flat on the sheet
    Above(front, bottom, gap=10)
    AlignLeft(front, bottom)
    Above(back, front, gap=10)
    AlignLeft(back, bottom)
    RightOf(end_l, bottom, gap=10)
    AlignBottom(end_l, bottom)
    RightOf(end_r, end_l, gap=10)
    AlignBottom(end_r, bottom)

    # assembled: box x -200..200, y -100..100, z 0..150
    Place(bottom, position=(0, 0, 0))
    Place(front, position=(0, -W / 2 + t, H / 2), rotation=(90 deg, 0, 0))
    Place(back, position=(0, W / 2, H / 2), rotation=(90 deg, 0, 0))
    Place(end_l, position=(-L / 2, 0, H / 2), rotation=(90 deg, 0, 90 deg))
    Place(end_r, position=(L / 2 - t, 0, H / 2), rotation=(90 deg, 0, 90 deg))

    # the request's numbers
    assert bottom.outline.width == 400 mm and bottom.outline.height == 200 mm, "box 400 x 200 outside"
    assert front.p.outline.height == 150 mm, "sides 150 mm tall"
    assert end_l.bb.height == 290 mm, "end panels 290 mm tall overall"
    assert end_l.grip.c.center.y - end_l.p.outline.bb.bottom == 250 mm, "dowel centre 250 mm up"
    assert end_l.grip.c.diameter == 28.5 mm, "28.5 mm dowel hole"
    assert label.word.size == 30 mm, "30 mm letters"
}
