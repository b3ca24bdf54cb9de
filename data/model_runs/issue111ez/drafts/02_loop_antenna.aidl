# Request: a frame for a medium-wave (AM) flat-spiral loop antenna, in 6 mm ply.
# Two arms 360 x 40 mm cross at their middles in cross-halvings (each slotted 20 mm deep from
# opposite long edges, 6 mm wide), so that the wire spiral lies in the plane through the arms'
# centre lines. Each arm end has 10 wire holes 2.5 mm across on the centre line, 6 mm apart,
# the innermost 110 mm from the arm's middle. The arms have 10 mm rounded corners, except the
# upright arm's foot, which is square and carries a 24 mm wide, 6 mm long tenon glued into a
# mortise in the base. The base is 160 x 100 mm, R8 corners: the mortise in its middle, a
# 7 mm shaft hole for the tuning capacitor 50 mm left of centre with two 2.7 mm screw holes
# 13 mm apart either side of it (on a line across the base), two 3.5 mm holes for terminal
# screws 50 mm right of centre, 16 mm apart; engraved "MW LOOP" (bold, filled, 8 mm) along the
# back edge and "TUNE" and "ANT" (4 mm) under the capacitor and the terminals.

import "std/joints.aidl"

thickness 6 mm

arm_l = 360 mm
arm_w = 40 mm
t = 6 mm
first_r = 110 mm
pitch = 6 mm
turns = 10

assembly loop_antenna {
    solid upright {
        body = RoundedRectangle(center=(0, 0), width=arm_w, height=arm_l, corner_radii=[10, 10, 0, 0])
        Fixed(body)
        # the tenon: the panel reaches down to the tenon's tip, the rest of the foot is cut back
        foot_ext = Rectangle(center=(0, -arm_l / 2 - t / 2), width=arm_w, height=t)
        tenon = tab_and_slot(part="tab", length=arm_w, thickness=t, tabs=1, tab=24, screw=0,
                             rotation=180, cx=0, cy=-arm_l / 2 - t)
        halving = cross_halving(depth=arm_w / 2, thickness=t, rotation=-90, cx=arm_w / 2, cy=0)
        hole wire {
            for k in range(turns) {
                up = Circle(center=(0, first_r + k * pitch), diameter=2.5)
                down = Circle(center=(0, -first_r - k * pitch), diameter=2.5)
            }
        }
    }

    solid crossbar {
        body = RoundedRectangle(center=(0, 0), width=arm_l, height=arm_w, corner_radius=10)
        Fixed(body)
        halving = cross_halving(depth=arm_w / 2, thickness=t, rotation=180, cx=0, cy=-arm_w / 2)
        hole wire {
            for k in range(turns) {
                right = Circle(center=(first_r + k * pitch, 0), diameter=2.5)
                left = Circle(center=(-first_r - k * pitch, 0), diameter=2.5)
            }
        }
    }

    solid base {
        body = RoundedRectangle(center=(0, 0), width=160, height=100, corner_radius=8)
        Fixed(body)
        mortise = tab_and_slot(part="slot", length=arm_w, thickness=t, tabs=1, tab=24, screw=0,
                               rotation=90, cx=0, cy=0)
        hole capacitor {
            shaft = Circle(center=(-50, 0), diameter=7)
            s1 = Circle(center=(-50, 6.5), diameter=2.7)
            s2 = Circle(center=(-50, -6.5), diameter=2.7)
        }
        hole terminals {
            a = Circle(center=(50, 8), diameter=3.5)
            b = Circle(center=(50, -8), diameter=3.5)
        }
        drawing labels {
            title = Text("MW LOOP", position=(0, 38), size=8, valign="middle", font="sans:Bold", fill=true)
            tune = Text("TUNE", position=(-50, -22), size=4, valign="middle")
            ant = Text("ANT", position=(50, -22), size=4, valign="middle")
        }
    }

    # on the sheet
    RightOf(crossbar, upright, gap=10)
    AlignTop(crossbar, upright)
    Below(base, crossbar, gap=10)
    AlignLeft(base, crossbar)

    # assembled: the base on the bench, the upright standing in it (its faces to the sides),
    # the crossbar lying flat through the upright's middle
    Place(base, position=(0, 0, 0), face="up")
    Place(upright, position=(-t / 2, 0, t + arm_l / 2), face="right", up="up")
    Place(crossbar, position=(0, 0, t + arm_l / 2 - t / 2), face="up")

    assert upright.body.bb.height == 360 mm, "arm 360 long"
    assert crossbar.body.bb.width == 360 mm, "arm 360 long"
    assert upright.body.bb.width == 40 mm and crossbar.body.bb.height == 40 mm, "arms 40 wide"
    assert len(upright.wire.up) == 10 and len(crossbar.wire.left) == 10, "10 holes per end"
    assert upright.wire.up[0].center.y - upright.body.center.y == 110 mm, "innermost hole 110 from the middle"
    assert upright.wire.up[1].center.y - upright.wire.up[0].center.y == 6 mm, "holes 6 apart"
    assert upright.body.bb.top - upright.wire.up[9].center.y >= 10 mm, "outermost hole well inside the end"
    assert upright.halving.cut.bb.width == 20 mm, "halving 20 deep"
    assert base.body.bb.width == 160 mm and base.body.bb.height == 100 mm, "base 160 x 100"
    assert distance(base.capacitor.s1.center, base.capacitor.s2.center) == 13 mm, "capacitor screws 13 apart"
    assert distance(base.terminals.a.center, base.terminals.b.center) == 16 mm, "terminals 16 apart"
    assert distance(base.labels.title, base.capacitor) >= 2 mm, "title clear of holes"
    assert distance(base.labels.tune, base.capacitor) >= 2 mm, "TUNE clear of the capacitor holes"
}
