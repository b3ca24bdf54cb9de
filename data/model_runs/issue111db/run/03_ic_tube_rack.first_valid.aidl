# Request: a bench rack for DIP IC tubes (the 530 mm anti-static tubes, about 13 x 8 mm in
# section), 3 mm plywood, glued. Two side cheeks 120 wide x 180 tall (corners rounded 8 mm),
# 300 mm apart outside, each with 10 tube openings 15 x 10 mm in 2 columns (centres 25 mm either
# side of the middle) and 5 rows 28 mm apart, the lowest 50 mm above the bench; each opening
# numbered 1-10 (engraved 5 mm, beside it on the outside), "IC TUBES" engraved up the middle.
# Two cross bars 40 mm tall stand at the bottom of the cheeks, 45 mm in front of and behind
# the middle, each with two 10 mm tabs per end glued into mortises through the cheeks.

import "std/joints.aidl"

thickness 3 mm

param width = 300 mm, min = 200 mm, max = 450 mm   # outside, cheek to cheek
cheek_w = 120 mm
cheek_h = 180 mm
bar_h = 40 mm
bar_off = 45 mm
row_pitch = 28 mm

def cheek() -> solid {
    body = RoundedRectangle(center=(0, 0), width=cheek_w, height=cheek_h, corner_radius=8)
    hole tube {
        r = Rectangle(center=(-25, -cheek_h / 2 + 50), width=15, height=10)
    }
    tubes = GridPattern(tube, 5, 2, (50, row_pitch))
    front_mortise = tab_and_slot(part="slot", length=bar_h, thickness=3 mm, tabs=2, tab=10 mm, screw=0,
                                 rotation=90 deg, cx=-bar_off, cy=-cheek_h / 2 + bar_h / 2)
    back_mortise = tab_and_slot(part="slot", length=bar_h, thickness=3 mm, tabs=2, tab=10 mm, screw=0,
                                rotation=90 deg, cx=bar_off, cy=-cheek_h / 2 + bar_h / 2)
    drawing labels {
        for r in range(5) {
            for c in range(2) {
                n = Text(str(r * 2 + c + 1), position=(-35.5 + 71 * c, -cheek_h / 2 + 50 + row_pitch * r),
                         size=5, anchor=("end" if c == 0 else "start"), valign="middle")
            }
        }
        title = Text("IC TUBES", position=(0, 15), size=7, valign="middle", rotation=90)
    }
}

def bar() -> solid {
    body = Rectangle(center=(0, 0), width=width, height=bar_h)
    left_tabs = tab_and_slot(part="tab", length=bar_h, thickness=3 mm, tabs=2, tab=10 mm, screw=0,
                             rotation=90 deg, cx=-width / 2, cy=0)
    right_tabs = tab_and_slot(part="tab", length=bar_h, thickness=3 mm, tabs=2, tab=10 mm, screw=0,
                              rotation=-90 deg, cx=width / 2, cy=0)
}

assembly ic_tube_rack {
    left = cheek()
    right = cheek()
    front_bar = bar()
    back_bar = bar()

    # on the sheet
    Fixed(left)
    RightOf(right, left, gap=5)
    AlignBottom(right, left)
    Below(front_bar, left, gap=5)
    AlignLeft(front_bar, left)
    Below(back_bar, front_bar, gap=5)
    AlignLeft(back_bar, front_bar)

    # in 3D: cheeks at x = +-150, bars on edge at y = -+45, all standing on z = 0
    Place(left, position=(-width / 2 + 3 mm, 0, cheek_h / 2), face="left", up="up")
    Place(right, position=(width / 2 - 3 mm, 0, cheek_h / 2), face="right", up="up")
    Place(front_bar, position=(0, -bar_off + 1.5 mm, bar_h / 2), face="front", up="up")
    Place(back_bar, position=(0, bar_off - 1.5 mm, bar_h / 2), face="back", up="up")

    assert len(left.tubes) == 10, "10 tube openings"
    assert left.tube.r.width == 15 mm and left.tube.r.height == 10 mm, "openings 15 x 10"
    assert left.tubes[1].r.center.x - left.tubes[0].r.center.x == 50 mm, "columns 25 mm either side"
    assert left.tubes[2].r.center.y - left.tubes[0].r.center.y == 28 mm, "rows 28 mm apart"
    assert left.tubes[0].r.center.y - left.body.bb.bottom == 50 mm, "lowest row 50 mm up"
    assert front_bar.body.width == 300 mm, "300 mm outside"
    assert left.body.width == 120 mm and left.body.height == 180 mm, "cheeks 120 x 180"
}
