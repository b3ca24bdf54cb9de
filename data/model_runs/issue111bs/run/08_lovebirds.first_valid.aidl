# Request: a tenth-anniversary gift, 6 mm cherry ply: two lovebirds facing each other on an
# oval base. Each bird (about 150 mm long) has an egg-shaped body (42 x 28 mm semi-axes,
# tipped up 20 degrees), a 34 mm round head, a pointed beak, a three-feathered tail, a 4 mm
# eye cut through, an engraved wing line and its owner's initial ("A" on the left bird, "B"
# on the right) engraved filled, 16 mm bold serif, on its body. It stands on a tapered foot
# (34 mm at the base, 14 mm at the body, 26 mm tall) with one 16 mm tenon glued into the base.
# The birds' beak tips 8 mm apart over the middle. The base an oval 220 x 90 mm with the two
# mortises on its long axis 140 mm apart, a filled 15 mm heart in front of the birds and
# "10 YEARS - 2016 - 2026" engraved filled, 8 mm bold, 28 mm in front of the long axis.

import "std/joints.aidl"

thickness 6 mm

GAP = 8 mm          # between the beak tips
BEAK = 66 mm        # beak tip's x from the foot's middle

def bird(s=1, initial="A") -> solid {
    # s = 1 faces +x, s = -1 faces -x; feet on y = 0 (the base's top), tenon tips on y = -6
    body = Ellipse(center=(0, 45), rx=42, ry=28, rotation=s * 20 deg)
    head = Circle(center=(s * 38, 80), radius=17)
    beak = Polygon([(s * 50, 86), (s * 66, 78), (s * 50, 72)])
    tail = Polygon([(s * -34, 36), (s * -78, 72), (s * -70, 56), (s * -82, 48), (s * -70, 40),
                    (s * -78, 26), (s * -36, 26)])
    foot = Trapezoid(center=(0, 7), bottom_width=34, top_width=14, height=26)
    tenon = tab_and_slot(part="tab", length=34 mm, thickness=6 mm, tabs=1, tab=16 mm, screw=0,
                         rotation=180 deg, cx=0 mm, cy=-6 mm)
    hole eye { c = Circle(center=(s * 42, 85), diameter=4) }
    drawing marks {
        # (attempt 1: W0513, the wing line ran through the initial: wing moved back, initial forward)
        wing = Ellipse(center=(s * -16, 50), rx=18, ry=10, rotation=s * 20 deg, start_angle=180 deg,
                       end_angle=360 deg)
        letter = Text(initial, position=(s * 14, 42), size=16, font="serif:Bold", valign="middle",
                      fill=true)
    }
}

assembly lovebirds {
    solid base {
        oval = Ellipse(center=(0, 0), rx=110, ry=45)
        Fixed(oval)
        left_mortise = tab_and_slot(part="slot", length=34 mm, thickness=6 mm, tabs=1, tab=16 mm,
                                    screw=0, cx=-70 mm, cy=0 mm)
        right_mortise = tab_and_slot(part="slot", length=34 mm, thickness=6 mm, tabs=1, tab=16 mm,
                                     screw=0, cx=70 mm, cy=0 mm)
        drawing words {
            # (attempt 1: E0405, the heart was 16.5 mm tall: circles r4 now, 15 mm)
            h1 = Hull(Circle(center=(-4, -10), radius=4), Point(0, -21), fill=true)
            h2 = Hull(Circle(center=(4, -10), radius=4), Point(0, -21), fill=true)
            t = Text("10 YEARS - 2016 - 2026", position=(0, -28), size=8, font="sans:Bold",
                     valign="top", fill=true)
        }
    }

    left_bird = bird(s=1, initial="A")
    right_bird = bird(s=-1, initial="B")

    # the sheet: the birds side by side above the base
    Above(left_bird, base, gap=10)
    AlignLeft(left_bird, base)
    RightOf(right_bird, left_bird, gap=10)
    AlignBottom(right_bird, left_bird)

    # 3D: the base on the table, the birds upright on its long axis, facing each other
    Place(base, position=(0, 0, 0))
    Place(left_bird, rotation=(90 deg, 0, 0), position=(-BEAK - GAP / 2, 3, 6))
    Place(right_bird, rotation=(90 deg, 0, 0), position=(BEAK + GAP / 2, 3, 6))

    # the request's numbers
    assert base.oval.bb.width == 220 mm and base.oval.bb.height == 90 mm, "base 220 x 90"
    assert base.right_mortise.slot[0].bb.center_x - base.left_mortise.slot[0].bb.center_x == 140 mm,
        "mortises 140 apart"
    assert 2 * (BEAK + GAP / 2) == 140 mm, "the birds stand on the mortises"
    assert left_bird.beak.bb.right - left_bird.foot.center.x == BEAK, "beak tip where reckoned"
    assert left_bird.head.radius * 2 == 34 mm, "34 mm head"
    assert left_bird.bb.width >= 140 mm and left_bird.bb.width <= 160 mm, "about 150 mm long"
    assert left_bird.foot.bb.height == 26 mm, "26 mm foot"
    assert base.words.h1.bb.top - base.words.h1.bb.bottom <= 15.5 mm, "15 mm heart"
    assert base.words.t.bb.top <= -28 mm + 0.5 mm, "text 28 mm in front"
}
