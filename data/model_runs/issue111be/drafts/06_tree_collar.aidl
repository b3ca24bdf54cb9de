# Request (holidays): a Christmas tree collar to hide the tree stand, 6 mm birch ply: four
# 450 x 250 mm walls (outer size) finger-jointed at the corners (30 mm fingers or more),
# open top and bottom, so it fits round a stand up to 430 mm across. The front has "NOEL" cut
# through as 80 mm bold stencil letters with a 36 mm star cut either side; the other three
# walls each have three 70 mm stars (5 points, rounded 2 mm tips) cut 130 mm apart in a row;
# the back also has a 36 mm semicircular notch in the middle of its bottom edge for the
# lights' cable.

units mm
thickness 6 mm

import "std/joints.aidl"

t = 6 mm
side = 450 mm
wall_h = 250 mm

def wall(ends="fingers", kind=1) -> solid {
    p = finger_panel(width=side, height=wall_h, thickness=t, finger=30, bottom="flat",
                     top="flat", left=ends, right=ends)
    Fixed(p)
    if kind == 0 {
        hole word {
            w = Text("NOEL", position=(0, 0), size=80, font="sans:Bold", valign="middle",
                     stencil=true)
        }
        hole stars {
            s = Star(center=(-185, 0), points=5, outer_radius=18, inner_radius=7,
                     tip_radius=1)
            s2 = Star(center=(185, 0), points=5, outer_radius=18, inner_radius=7,
                      tip_radius=1)
        }
    } else {
        hole stars {
            for i in range(3) {
                s = Star(center=((i - 1) * 130, 10), points=5, outer_radius=35,
                         inner_radius=14, tip_radius=2)
            }
        }
    }
    if kind == 2 {
        hole cable { c = Circle(center=(0, -wall_h / 2), diameter=36) }
    }
}

assembly tree_collar {
    front = wall(ends="fingers", kind=0)
    back = wall(ends="fingers", kind=2)
    left = wall(ends="slots", kind=1)
    right = wall(ends="slots", kind=1)

    # on the sheet: a 2 x 2 grid
    # FIX after the first valid program: W0511, back and right overlapped on the sheet: the
    # cable notch pokes past the back's bottom edge and widens its box, so AlignBottom on the
    # whole part lifted the back 18 mm; align the panels themselves
    RightOf(back, front, gap=8)
    AlignBottom(back.p, front.p)
    Above(left, front, gap=8)
    AlignLeft(left, front)
    RightOf(right, left, gap=8)
    AlignBottom(right, left)

    # in 3D: a square ring of walls standing on the floor, outer faces at +-225
    Place(front, position=(0, -side / 2 + t, wall_h / 2), rotation=(90 deg, 0, 0))
    Place(back, position=(0, side / 2 - t, wall_h / 2), rotation=(90 deg, 0, 180 deg))
    Place(left, position=(-side / 2 + t, 0, wall_h / 2), rotation=(90 deg, 0, -90 deg))
    Place(right, position=(side / 2 - t, 0, wall_h / 2), rotation=(90 deg, 0, 90 deg))

    assert front.p.outline.width == 450 mm and front.p.outline.height == 250 mm, "450 x 250"
    assert left.p.outline.width == 450 mm, "sides 450"
    assert side - 2 * t >= 430 mm, "fits a 430 mm stand"
    assert front.word.w.size == 80 mm, "80 mm letters"
    assert len(back.stars.s) == 3, "three stars"
    assert back.stars.s[1].center.x - back.stars.s[0].center.x == 130 mm, "130 apart"
    assert back.stars.s[0].outer_radius * 2 == 70 mm, "70 mm stars"
    assert front.stars.s.outer_radius * 2 == 36 mm, "36 mm stars by the word"
    assert back.cable.c.diameter == 36 mm, "36 mm cable notch"
    assert back.cable.c.center.y == back.p.outline.bottom.midpoint.y, "notch on the bottom edge"
    # the front's stars clear the word and the finger joints
    assert front.word.w.bb.left - front.stars.s.bb.right >= 5 mm, "left star clears NOEL"
    assert front.stars.s2.bb.left - front.word.w.bb.right >= 5 mm, "right star clears NOEL"
    assert front.stars.s.bb.left - front.p.outline.left.midpoint.x >= t + 5 mm, "star clears the fingers"
}
