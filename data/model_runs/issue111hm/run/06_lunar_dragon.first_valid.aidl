# Request (holidays): a Lunar New Year dragon to hang in the window, 3 mm ply, about
# 320 mm long. A head, three body segments and a tail, joined with 4 mm brass paper
# fasteners (4.2 mm holes) so it wiggles; 63 mm from joint to joint along the body. Each
# body segment is an oval 70 x 52 mm with a round lobe at the front that carries its joint,
# three 12 mm spines on its back and engraved scales (five half-circles of 7 mm radius). The
# head faces left: a long snout, an open mouth, a swept-back horn, a 10 mm eye hole. The
# tail is a teardrop (22 mm round end, 75 mm long) with "福" (good fortune) engraved filled,
# 14 mm. A 3 mm ribbon hole in the head and one in the tail to hang it.

thickness 3 mm

PIN = 4.2 mm
FRONT = -38 mm      # a segment's front joint from its centre
BACK = 25 mm        # its back joint
PITCH = 63 mm

def segment() -> solid {
    body = Ellipse(center=(0, 0), rx=35, ry=26)
    lobe = Circle(center=(FRONT, 0), radius=11)
    for k in range(3) {
        spine = Triangle(center=(-15 + k * 15, 28), base=12, height=12)
    }
    hole front_pin { c = Circle(center=(FRONT, 0), diameter=PIN) }
    hole back_pin { c = Circle(center=(BACK, 0), diameter=PIN) }
    drawing scales {
        for i in range(3) {
            top_row = Arc(center=(-20 + i * 14, 4), radius=7, start_angle=180 deg,
                          end_angle=360 deg)
        }
        for i in range(2) {
            low_row = Arc(center=(-13 + i * 14, -8), radius=7, start_angle=180 deg,
                          end_angle=360 deg)
        }
    }
}

assembly lunar_dragon {
    solid head {
        outline = Spline([(-60, 2), (-52, 14), (-30, 20), (-14, 30), (8, 56), (6, 30),
                          (28, 24), (44, 10), (44, -12), (22, -26), (-20, -24),
                          (-45, -14), (-58, -12), (-40, -5)],
                         closed=true, corners=[0, 4, 5, 12, 13])
        hole eye { c = Circle(center=(-22, 8), diameter=10) }
        hole back_pin { c = Circle(center=(30, 0), diameter=PIN) }
        hole ribbon { c = Circle(center=(12, 18), diameter=3) }
        drawing face {
            nostril = Circle(center=(-50, 6), radius=1.5)
            brow = Arc(start=(-34, 14), through=(-22, 19), end=(-10, 16))
        }
    }
    seg1 = segment()
    seg2 = segment()
    seg3 = segment()
    solid tail {
        body = Hull(Circle(center=(0, 0), radius=22), Point(75, 18))
        hole front_pin { c = Circle(center=(-10, 0), diameter=PIN) }
        hole ribbon { c = Circle(center=(40, 10), diameter=3) }
        drawing luck {
            fu = Text("福", (12, 0), size=14, font="Droid Sans Fallback", valign="middle",
                      fill=true)
        }
    }

    head.bb.center == (-120, 60)
    seg1.bb.center == (0, 60)
    seg2.bb.center == (100, 60)
    seg3.bb.center == (-120, -30)
    tail.bb.center == (0, -30)

    # hung: every joint over the next part's, the parts alternately on two layers
    Place(head, position=(0, 0, 0))
    Place(seg1, position=(30 mm - FRONT, 0, 3 mm))
    Place(seg2, position=(30 mm - FRONT + PITCH, 0, 0))
    Place(seg3, position=(30 mm - FRONT + 2 * PITCH, 0, 3 mm))
    Place(tail, position=(30 mm - FRONT + 2 * PITCH + BACK + 10 mm, 0, 0))

    assert seg1.back_pin.c.center.x - seg1.front_pin.c.center.x == 63 mm, "63 mm pitch"
    assert seg1.body.rx * 2 == 70 mm and seg1.body.ry * 2 == 52 mm, "oval 70 x 52"
    assert len(seg1.spine) == 3, "three spines"
    assert len(seg1.scales.top_row) + len(seg1.scales.low_row) == 5, "five scales"
    assert seg1.front_pin.c.diameter == 4.2 mm, "4.2 mm joint holes"
    assert head.eye.c.diameter == 10 mm, "10 mm eye"
    assert tail.body.bb.right - tail.body.bb.left == 22 mm + 75 mm, "tail 22 + 75 long"
    # the joints keep wood round them: 3 mm from the pin hole to the lobe's edge
    assert seg1.lobe.radius - PIN / 2 >= 3 mm, "wood round the front joint"
    assert distance(seg1.back_pin, seg1.scales) >= 2 mm, "scales clear of the back joint"
    assert distance(tail.luck, tail.front_pin) >= 2 mm, "character clear of the joint"
    # about 320 mm long, head to tail
    assert (30 mm - FRONT + 2 * PITCH + BACK + 10 mm + 75 mm) - (-60 mm) >= 300 mm,
        "about 320 long"
}
