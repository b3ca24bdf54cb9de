# Request (electronics): a desk stand for a 120 mm USB PC fan, cut from 3 mm acrylic, glued.
# - Front plate 140 mm wide, 143 mm tall (to the tips of its bottom tabs), top corners
#   rounded 8 mm. A 116 mm round opening for the fan, its centre 70 mm above the base's top
#   face, and four M4 holes (4.5 mm) on the fan's 105 mm square. Two 30 mm tabs on the bottom
#   edge go down into the base.
# - Base 160 x 90 mm, corners rounded 6 mm; the front plate's slots 15 mm behind the base's
#   front edge; the words "USB FAN" engraved in 6 mm letters in front of the plate.
# - Two right-triangle braces behind the plate, 60 mm deep and 80 mm tall (from the plate's
#   back face and the base's top face), centred 64 mm either side of the middle. Each has
#   one 40 mm tab in the middle of its front edge into a slot in the front plate and one
#   30 mm tab in the middle of its bottom edge into a slot in the base.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
plate_w = 140 mm
plate_h = 143 mm
fan_rise = 70 mm        # fan centre above the base's top face
brace_x = 64 mm
brace_d = 60 mm
brace_h = 80 mm

def brace() -> solid {
    # the right angle at (0, 0): the front edge along x = 0 and the bottom edge along y = 0
    # are the tabs' tips; the shoulders stand t in from them
    body = Polygon([(0, 0), (brace_d + t, 0), (0, brace_h + t)])
    bottom_tab = tab_and_slot(part="tab", length=brace_d + t, thickness=t, tabs=1, tab=30,
                              screw=0, cx=(brace_d + t) / 2, cy=0)
    front_tab = tab_and_slot(part="tab", length=brace_h + t, thickness=t, tabs=1, tab=40,
                             screw=0, rotation=90 deg, cx=0, cy=(brace_h + t) / 2)
}

assembly fan_stand {
    solid front {
        body = RoundedRectangle(bottom_left=(-plate_w / 2, 0), width=plate_w, height=plate_h,
                                corner_radii=[8, 8, 0, 0])
        feet = tab_and_slot(part="tab", length=plate_w, thickness=t, tabs=2, tab=30, screw=0,
                            cx=0, cy=0)
        hole opening {
            c = Circle(center=(0, t + fan_rise), diameter=116)
        }
        hole screws {
            for i in range(4) {
                h = Circle(center=((i % 2 - 0.5) * 105, t + fan_rise + (i // 2 - 0.5) * 105),
                           diameter=4.5)
            }
        }
        left_slot = tab_and_slot(part="slot", length=brace_h + t, thickness=t, tabs=1, tab=40,
                                 screw=0, rotation=90 deg, cx=-brace_x, cy=(brace_h + t) / 2)
        right_slot = tab_and_slot(part="slot", length=brace_h + t, thickness=t, tabs=1, tab=40,
                                  screw=0, rotation=90 deg, cx=brace_x, cy=(brace_h + t) / 2)
    }

    solid base {
        body = RoundedRectangle(center=(0, 0), width=160, height=90, corner_radius=6)
        plate_slots = tab_and_slot(part="slot", length=plate_w, thickness=t, tabs=2, tab=30,
                                   screw=0, cx=0, cy=45 - 15 - t / 2)
        # a brace's bottom tab: centred (brace_d + t) / 2 from its tip line, which lies in
        # the front plate's front face
        left_slot = tab_and_slot(part="slot", length=brace_d + t, thickness=t, tabs=1, tab=30,
                                 screw=0, rotation=90 deg, cx=-brace_x,
                                 cy=45 - 15 - (brace_d + t) / 2)
        right_slot = tab_and_slot(part="slot", length=brace_d + t, thickness=t, tabs=1, tab=30,
                                  screw=0, rotation=90 deg, cx=brace_x,
                                  cy=45 - 15 - (brace_d + t) / 2)
        drawing label {
            w = Text("USB FAN", position=(0, 45 - 7.5), size=6, valign="middle")
        }
    }

    left_brace = brace()
    right_brace = brace()

    RightOf(base, front, gap=10)
    AlignBottom(base, front)
    RightOf(left_brace, base, gap=10)
    AlignBottom(left_brace, base)
    RightOf(right_brace, left_brace, gap=10)
    AlignBottom(right_brace, left_brace)

    assert front.body.bb.height == 143 mm
    assert front.opening.c.center.y - (front.body.bb.bottom + t) == 70 mm, "fan centre 70 mm above the base"
    assert front.screws.h[1].center.x - front.screws.h[0].center.x == 105 mm
    assert front.screws.h[2].center.y - front.screws.h[0].center.y == 105 mm
    assert distance(front.opening, front.right_slot) >= 3 mm
    assert distance(front.screws, front.right_slot) >= 3 mm
    assert front.right_slot.slot[0].bb.center_x - front.body.bb.center_x == 64 mm
    assert base.body.bb.top - base.plate_slots.slot[0].bb.top == 15 mm
    assert base.right_slot.slot[0].bb.center_x - base.body.bb.center_x == 64 mm
    assert distance(base.label, base.plate_slots) >= 2 mm
    assert left_brace.body.bb.width == 63 mm and left_brace.body.bb.height == 83 mm
}
