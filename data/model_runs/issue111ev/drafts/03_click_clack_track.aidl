# Request: a click-clack track (the zig-zag ramp toy that a little wooden car rattles down),
# cut from 6 mm birch ply and glued.
# - Two identical side panels 200 wide x 300 tall, top corners R20, a 120 mm wide x 8 mm
#   high relief in the bottom edge (two feet), a 60 x 16 mm carry slot with its centre 15 mm
#   under the top, "CLICK CLACK" engraved 10 mm tall, its middle 40 mm above the bottom.
# - Three ramps, each 150 mm long along the slope and 90 mm wide between the sides, tilted
#   12 degrees, alternating: the top one runs down to the right, the middle one to the left,
#   the bottom one to the right. Ramp centres 75 mm apart in height, the top one 240 mm up;
#   the ramps that run right sit 10 mm left of the side's centre, the left-running one 10 mm
#   right, so each ramp's low end overhangs the high end of the one below.
# - Each ramp has two 30 mm glue tabs (6 mm long) on each long edge into mortises in the
#   sides, 0.2 mm clearance.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
side_w = 200 mm
side_h = 300 mm
ramp_len = 150 mm
inner = 90 mm
slope = 12 deg
pitch = 75 mm
top_y = 240 mm
shift = 10 mm

def ramp_x(i) = -shift if i % 2 == 0 else shift
def ramp_y(i) = top_y - i * pitch
def ramp_a(i) = -slope if i % 2 == 0 else slope

# FIX after the first valid program: both sides stand facing front (their mortises must match),
# so the back side's engraving faced inward; only the front side is engraved now.
def side(label=true) -> solid {
    body = RoundedRectangle(bottom_left=(-side_w / 2, 0), width=side_w, height=side_h,
                            corner_radii=[20, 20, 0, 0])
    hole feet {
        r = Rectangle(center=(0, 4), width=120, height=8)
        o = Rectangle(center=(0, -1), width=120, height=2, overrun=true)
    }
    hole carry {
        s = Slot(center=(0, side_h - 15), length=60, width=16)
    }
    for i in range(3) {
        m = tab_and_slot(part="slot", length=ramp_len, thickness=t, tabs=2, tab=30 mm, screw=0,
                         clearance=0.2 mm, rotation=ramp_a(i), cx=ramp_x(i), cy=ramp_y(i))
    }
    if label {
        drawing title {
            w = Text("CLICK CLACK", position=(0, 40), size=10, valign="middle")
        }
    }
}

def ramp() -> solid {
    body = Rectangle(center=(0, 0), width=ramp_len, height=inner + 2 * t)
    a = tab_and_slot(part="tab", length=ramp_len, thickness=t, tabs=2, tab=30 mm, screw=0,
                     cx=0 mm, cy=inner / 2 + t)
    b = tab_and_slot(part="tab", length=ramp_len, thickness=t, tabs=2, tab=30 mm, screw=0,
                     rotation=180 deg, cx=0 mm, cy=-inner / 2 - t)
}

assembly click_clack {
    front = side()
    back = side(label=false)
    for i in range(3) {
        r = ramp()
    }

    # flat on the sheet
    RightOf(back, front, gap=6)
    AlignBottom(back, front)
    Below(r[0], front, gap=6)
    AlignLeft(r[0], front)
    RightOf(r[1], r[0], gap=6)
    AlignTop(r[1], r[0])
    RightOf(r[2], r[1], gap=6)
    AlignTop(r[2], r[1])

    # 3D: the sides stand at y = -45 and +45 (inner faces), both facing front; each ramp
    # tilted about y, its bottom face half a thickness under the mortise's centre line
    Place(front, position=(0, -inner / 2, 0), face="front", up="up")
    Place(back, position=(0, inner / 2 + t, 0), face="front", up="up")
    for i in range(3) {
        Place(r[i], position=(ramp_x(i) + t / 2 * sin(ramp_a(i)), 0,
                              ramp_y(i) - t / 2 * cos(ramp_a(i))),
              rotation=(0, -ramp_a(i), 0))
    }

    assert front.body.bb.width == 200 mm and front.body.bb.height == 300 mm, "sides 200 x 300"
    assert r[0].body.bb.width == 150 mm, "ramps 150 long"
    assert r[0].body.bb.height - 2 * t == 90 mm, "90 mm between the sides"
    assert len(r) == 3, "three ramps"
    assert len(front.m) == 3, "three mortise pairs per side"
    assert ramp_y(0) - ramp_y(1) == 75 mm, "ramps 75 apart"
    assert ramp_x(0) + 10 mm == 0 mm and ramp_x(1) - 10 mm == 0 mm, "ramps offset 10 mm"
    # the low end of each ramp overhangs the high end of the next
    assert ramp_x(0) + ramp_len / 2 * cos(slope) < ramp_x(1) + ramp_len / 2 * cos(slope), "overhang"
    assert ramp_x(1) - ramp_len / 2 * cos(slope) > ramp_x(2) - ramp_len / 2 * cos(slope), "overhang"
    assert front.carry.s.center.y - front.body.bb.top == -15 mm, "carry slot 15 under the top"
    assert distance(front.title, front.m[2]) >= 3 mm, "title clear of the bottom ramp"
    assert distance(front.title, front.feet) >= 3 mm, "title clear of the feet"
}
