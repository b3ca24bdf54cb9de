# Request: a desk rack for 12 audio cassettes standing side by side like books (cases
# 110 x 70 x 17 mm), 4 mm ply.
# - Inside length 210 mm (12 x 17 mm + 6 mm play) between two end panels shaped like a big
#   cassette: 100 mm deep x 64 mm tall, R5 corners, two 18 mm reel holes 40 mm apart and a
#   16 x 10 mm window between them, 34 mm up; an engraved label strip 84 x 14 mm (R3) at the
#   top with "MIXTAPES" (right end) or "VOL. 1" (left end), bold 7 mm, filled; an engraved
#   tape-head trapezoid (60 mm at the bottom, 48 at the top, 12 tall) under the reels.
# - Base 92 mm deep, 4 mm above the desk, glued into both ends by 3 tabs of 15 mm.
# - Back wall 40 mm tall on the base, 4 mm in from its back edge, glued into the base by
#   3 tabs of 30 mm and into each end by one 20 mm tab. At least 70 mm in front of it.

import "std/joints.aidl"

thickness 4 mm

T = 4 mm
INNER = 210 mm     # between the end panels
BASE_D = 92 mm
BASE_Z = 4 mm      # base underside over the desk
BACK_Y = 40 mm     # middle of the back wall, from the base's centre line
BACK_H = 40 mm

def end_panel(s=1, word="MIXTAPES") -> solid {
    # frame: x runs along the rack's depth (s = -1 mirrors it for the left end),
    # y is the height over the desk
    body = RoundedRectangle(center=(0, 32), width=100, height=64, corner_radius=5)
    hole reels {
        a = Circle(center=(-20, 34), diameter=18)
        b = Circle(center=(20, 34), diameter=18)
        w = RoundedRectangle(center=(0, 34), width=16, height=10, corner_radius=2)
    }
    base_mortise = tab_and_slot(part="slot", length=BASE_D, thickness=T, tabs=3, tab=15 mm,
                                screw=0, cx=0 mm, cy=BASE_Z + T / 2)
    back_mortise = tab_and_slot(part="slot", length=BACK_H, thickness=T, tabs=1, tab=20 mm,
                                screw=0, rotation=90 deg, cx=s * BACK_Y,
                                cy=BASE_Z + T + BACK_H / 2)
    drawing deco {
        label = RoundedRectangle(center=(0, 53), width=84, height=14, corner_radius=3)
        t = Text(word, position=(0, 53), size=7, font="sans:Bold", fill=true, valign="middle")
        head = Trapezoid(center=(0, 15), bottom_width=60, top_width=48, height=12)
    }
}

assembly cassette_rack {
    right_end = end_panel(s=1, word="MIXTAPES")
    left_end = end_panel(s=-1, word="VOL. 1")

    solid base {
        # x along the rack, y along its depth; the tabs' tips are the ends' outer faces
        body = Rectangle(center=(0, 0), width=INNER + 2 * T, height=BASE_D)
        tabs_r = tab_and_slot(part="tab", length=BASE_D, thickness=T, tabs=3, tab=15 mm,
                              screw=0, rotation=-90 deg, cx=INNER / 2 + T, cy=0 mm)
        tabs_l = tab_and_slot(part="tab", length=BASE_D, thickness=T, tabs=3, tab=15 mm,
                              screw=0, rotation=90 deg, cx=-INNER / 2 - T, cy=0 mm)
        back_mortise = tab_and_slot(part="slot", length=INNER, thickness=T, tabs=3,
                                    tab=30 mm, screw=0, cx=0 mm, cy=BACK_Y)
    }

    solid back {
        # y = 0 is the base's top face; the bottom tabs reach down through the base
        wall = Rectangle(center=(0, BACK_H / 2), width=INNER + 2 * T, height=BACK_H)
        foot = Rectangle(center=(0, -T / 2), width=INNER, height=T)
        tabs_down = tab_and_slot(part="tab", length=INNER, thickness=T, tabs=3, tab=30 mm,
                                 screw=0, rotation=180 deg, cx=0 mm, cy=-T)
        tabs_r = tab_and_slot(part="tab", length=BACK_H, thickness=T, tabs=1, tab=20 mm,
                              screw=0, rotation=-90 deg, cx=INNER / 2 + T, cy=BACK_H / 2)
        tabs_l = tab_and_slot(part="tab", length=BACK_H, thickness=T, tabs=1, tab=20 mm,
                              screw=0, rotation=90 deg, cx=-INNER / 2 - T, cy=BACK_H / 2)
    }

    # flat layout
    Below(base, back, gap=8)
    AlignCenterX(base, back)
    LeftOf(left_end, base, gap=8)
    AlignTop(left_end, base)
    RightOf(right_end, base, gap=8)
    AlignTop(right_end, base)

    # 3D
    Place(right_end, position=(INNER / 2, 0, 0), face="right", up="up")
    Place(left_end, position=(-INNER / 2, 0, 0), face="left", up="up")
    Place(base, position=(0, 0, BASE_Z), face="up", up="back")
    Place(back, position=(0, BACK_Y + T / 2, BASE_Z + T), face="front", up="up")

    # the request's numbers
    assert base.body.bb.width - 2 * T == 12 * 17 mm + 6 mm, "room for 12 cases + 6 mm"
    assert right_end.body.bb.width == 100 mm and right_end.body.bb.height == 64 mm,
        "ends 100 x 64"
    assert right_end.reels.b.center.x - right_end.reels.a.center.x == 40 mm, "reels 40 apart"
    assert right_end.reels.a.diameter == 18 mm, "18 mm reels"
    assert base.body.bb.height == 92 mm, "base 92 deep"
    assert back.wall.bb.height == 40 mm, "back 40 tall"
    assert base.body.bb.top - (BACK_Y + T / 2) == 4 mm, "back 4 mm in from the base's edge"
    assert (BACK_Y - T / 2) - base.body.bb.bottom >= 70 mm, "70 mm for the cases"
}
