# Request: an Ames window (the rotating-trapezoid illusion) for a science fair, on a slow
# turntable motor (49TYJ).
# - window, 3 mm plywood: a trapezoid 240 mm wide, its tall edge 140 mm, its short edge 70 mm,
#   both vertical and centred on one line (the top and bottom edges meet 480 mm from the tall
#   edge). It is drawn as a window of 3 x 2 panes seen in perspective: a point at (u, v) of the
#   flat window (u 0..1 from the tall edge, v -1..1 from the bottom) lands at
#   x = 480 u / (1 + u), y = 70 v / (1 + u) mm. Borders 0.06 in u and 0.14 in v, bars 0.04 in u
#   (at u = 1/3 and 2/3: x = 120 and 192 mm) and 0.12 in v (at v = 0). Painted-looking shadows:
#   an L of filled engraving along the top and the tall-edge side of each pane, 0.015 in u and
#   0.05 in v wide. Below it, a stem 60 mm wide at x 130..190 reaching 3 mm into the bottom border
#   and down to 80 mm below the middle line, ending in two glued tabs 12 mm wide (tab and slot)
#   into the turntable disc.
# - disc, 3 mm plywood, 100 mm: the two mortises, centred, and a 7 mm hole for the motor's shaft
#   between them (the turning axis goes through the window at x = 160 mm, its true middle).
# - base, 3 mm plywood, 200 x 140 mm R10, to screw onto the motor's box: a 10 mm hole for the motor's
#   boss under the disc, two M4 holes (4.5 mm) 56 mm apart either side of it, and "AMES WINDOW"
#   (8 mm bold letters, filled) in front of the disc.

import "std/joints.aidl"

thickness 3 mm

VP = 480 mm          # where the top and bottom edges meet
H0 = 70 mm           # half the tall edge
AXIS_X = 160 mm      # the window's true middle (u = 0.5)

def P(u, v) = (VP * u / (1 + u), v * H0 / (1 + u))
def UX(x) = x / (VP - x)
def UA(i) = i / 3 + (0.06 if i == 0 else 0.02)
def UB(i) = (i + 1) / 3 - (0.06 if i == 2 else 0.02)
def VA(j) = 0.06 if j == 0 else -0.86
def VB(j) = 0.86 if j == 0 else -0.06

assembly ames {
    solid window {
        frame = Polygon([P(0, -1), P(1, -1), P(1, 1), P(0, 1)])
        stem = Polygon([(130 mm, -80 mm), (190 mm, -80 mm),
                        (190 mm, P(UX(190 mm), -1)[1] + 3 mm),
                        (130 mm, P(UX(130 mm), -1)[1] + 3 mm)])
        # FIX after the first valid program: the stem is above its bottom edge, so the joint
        # is turned 180 deg (W0502, W0517: the gaps were cut below the stem, in the air)
        feet = tab_and_slot(part="tab", length=60 mm, thickness=3 mm, tabs=2, tab=12 mm,
                            screw=0, rotation=180 deg, cx=AXIS_X, cy=-80 mm)
        hole panes {
            for i in range(3) {
                for j in range(2) {
                    p = Polygon([P(UA(i), VA(j)), P(UB(i), VA(j)), P(UB(i), VB(j)),
                                 P(UA(i), VB(j))])
                }
            }
        }
        drawing shadows {
            for i in range(3) {
                for j in range(2) {
                    s = Polygon([P(UA(i) - 0.015, VA(j)), P(UA(i), VA(j)), P(UA(i), VB(j)),
                                 P(UB(i), VB(j)), P(UB(i), VB(j) + 0.05),
                                 P(UA(i) - 0.015, VB(j) + 0.05)], fill=true)
                }
            }
        }
    }

    solid disc {
        plate = Circle(center=(0, 0), diameter=100 mm)
        mortises = tab_and_slot(part="slot", length=60 mm, thickness=3 mm, tabs=2, tab=12 mm,
                                screw=0, cx=0 mm, cy=0 mm)
        hole shaft {
            c = Circle(center=(0, 0), diameter=7 mm)
        }
    }

    solid base {
        plate = RoundedRectangle(center=(0, 0), width=200 mm, height=140 mm, corner_radius=10 mm)
        hole motor {
            boss = Circle(center=(0, 0), diameter=10 mm)
            left = Circle(center=(-28 mm, 0), diameter=4.5 mm)
            right = Circle(center=(28 mm, 0), diameter=4.5 mm)
        }
        drawing name {
            t = Text("AMES WINDOW", position=(0, -60 mm), size=8 mm, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    # flat on the sheet
    Below(disc, window, gap=8 mm)
    AlignLeft(disc, window)
    RightOf(base, disc, gap=8 mm)
    AlignTop(base, disc)

    # in 3D: the base on the motor's box, the disc 2 mm above it, the window standing on the disc
    # with its true middle on the axis
    Place(base, position=(0, 0, 0))
    Place(disc, position=(0, 0, 5 mm))
    Place(window, position=(-AXIS_X, 1.5 mm, 85 mm), face="front", up="up")

    assert window.frame.bb.width == 240 mm, "240 wide"
    assert window.frame.points[3].y - window.frame.points[0].y == 140 mm, "tall edge 140"
    assert window.frame.points[2].y - window.frame.points[1].y == 70 mm, "short edge 70"
    assert window.frame.points[0].x == window.frame.points[3].x and
        window.frame.points[1].x == window.frame.points[2].x, "both edges vertical"
    assert len(window.panes.p) == 3 and len(window.panes.p[0]) == 2, "3 x 2 panes"
    assert window.panes.p[0][0].points[1].x < 120 mm and window.panes.p[1][0].points[0].x > 120 mm,
        "first bar round x = 120"
    assert window.panes.p[1][0].points[1].x < 192 mm and window.panes.p[2][0].points[0].x > 192 mm,
        "second bar round x = 192"
    assert window.stem.bb.width == 60 mm and window.stem.bb.left - window.frame.bb.left == 130 mm,
        "stem 60 wide at x 130..190"
    assert window.frame.points[0].y - window.stem.bb.bottom == 80 mm - 70 mm, "stem to 80 below"
    assert distance(window.stem, window.panes) >= 2 mm, "stem clear of the panes"
    assert window.feet.gap[0].bb.height == 3 mm, "tabs 3 mm long"
    assert disc.plate.diameter == 100 mm, "100 mm disc"
    assert disc.shaft.c.diameter == 7 mm, "7 mm shaft hole"
    assert distance(disc.shaft, disc.mortises) >= 3 mm, "shaft hole clear of the mortises"
    assert base.plate.bb.width == 200 mm and base.plate.bb.height == 140 mm, "base 200 x 140"
    assert base.motor.right.center.x - base.motor.left.center.x == 56 mm, "M4 holes 56 apart"
    assert base.motor.boss.diameter == 10 mm, "10 mm boss hole"
    assert distance(base.name, base.motor) >= 5 mm, "name clear of the holes"
    assert base.name.bb.top <= base.plate.bb.center_y - 50 mm, "name in front of the disc"
}
