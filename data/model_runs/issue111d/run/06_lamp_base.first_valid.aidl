# Cross-halved lamp base (home): two panels of 3 mm plywood slotted into each other crosswise;
# each panel a trapezoid 140 mm wide at the bottom, 60 mm at the top, 160 mm tall; panel A
# slotted 80 mm down from the middle of its top edge, panel B 80 mm up from the middle of its
# bottom edge, slots 3.2 mm wide (3 mm + 0.2 mm clearance); in each panel two round-topped
# arch windows 16 mm wide x 40 mm tall (R8 top), centered 22 mm either side of the center line,
# their bottoms 25 mm above the bottom edge; panel B has a cord notch 8 mm wide x 10 mm tall
# (round top) in its bottom edge, 30 mm right of the center line.

import "std/joints.aidl"

thickness 3 mm

param overlap = 160 mm, min = 120 mm, max = 200 mm

def lamp_panel(top_slot=true) -> solid {
    body = Trapezoid(center=(0, 0), bottom_width=140, top_width=60, height=overlap)
    hole window {
        w = RoundedRectangle(center=(-22, -overlap / 2 + 25 + 20), width=16, height=40,
                             corner_radii=[8, 8, 0, 0])
    }
    axis = Line((0, -overlap / 2), (0, overlap / 2), construction=true)
    other = Mirrored(window, about=axis)
    if top_slot {
        s = cross_halving(depth=overlap / 2, thickness=3 mm, clearance=0.2 mm, cx=0, cy=overlap / 2)
    } else {
        s = cross_halving(depth=overlap / 2, thickness=3 mm, clearance=0.2 mm, rotation=180 deg,
                          cx=0, cy=-overlap / 2)
    }
}

assembly lamp {
    a = lamp_panel(top_slot=true)
    b = lamp_panel(top_slot=false)
    RightOf(b, a, gap=10)
    AlignBottom(b, a)

    hole cord {
        n = RoundedRectangle(center=(0, 0), width=8, height=10, corner_radii=[4, 4, 0, 0])
    }
    cord.bb.bottom == b.body.bb.bottom
    cord.bb.center_x == b.body.bb.center_x + 30 mm
    CutInto(cord, b)

    assert a.body.bb.width == 140 mm, "140 mm at the bottom"
    assert a.body.top_width == 60 mm, "60 mm at the top"
    assert a.body.bb.height == 160 mm, "160 mm tall"
    assert a.s.cut.bb.height == 80 mm, "A slotted 80 mm from the top"
    assert b.s.cut.bb.height == 80 mm, "B slotted 80 mm from the bottom"
    assert a.s.cut.bb.top == a.body.bb.top, "A's slot opens at the top"
    assert b.s.cut.bb.bottom == b.body.bb.bottom, "B's slot opens at the bottom"
    assert a.s.cut.bb.width == 3.2 mm, "3.2 mm slots"
    assert a.window.w.bb.width == 16 mm and a.window.w.bb.height == 40 mm, "16 x 40 mm windows"
    assert a.window.w.bb.bottom - a.body.bb.bottom == 25 mm, "windows 25 mm above the bottom"
    assert a.body.bb.center_x - a.window.w.bb.center_x == 22 mm, "windows 22 mm off the center line"
    assert cord.bb.width == 8 mm and cord.bb.height == 10 mm, "8 x 10 mm cord notch"
}
