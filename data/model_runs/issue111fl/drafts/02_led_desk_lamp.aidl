# Request: a small LED desk lamp from 6 mm birch ply, five parts. A round base 180 mm across,
# with four countersunk M4 holes on a 110 mm circle (45, 135, ... deg) for a steel weight
# plate underneath. An upright 50 wide standing 140 mm above the base on two tenons, its top
# a half-round R25 with a 5.5 mm pivot hole (M5 bolt and wing nut) at the round's centre; in
# it a round 8 mm hole for a 5.5 x 2.1 DC panel jack 30 mm up (engraved "5V DC" under it), a
# 13 x 19 mm cut-out for a KCD1 rocker switch 70 mm up (long side vertical, "I" engraved above
# and "O" below) and a 6 mm cable hole 94 mm up. One arm 30 wide with round ends, 220 mm
# between its two 5.5 mm pivot holes, with three pairs of zip-tie slots (5 x 2.5) for the cable
# at 60, 110 and 160 mm from the lower pivot. The head: a plate 220 x 50 (R10 corners) carrying
# a 10 mm LED strip underneath, "LUMEN" engraved on top, a 5 mm cable hole, and an ear 40 wide
# standing on it 40 mm from its back end (one tenon) with its pivot hole 20 mm below its round
# top and 26 mm above the head's underside. Assembled: arm at 60 degrees, head level.

units mm
thickness 6 mm
import "std/joints.aidl"

T = 6 mm
PIVOT = 5.5 mm
ARM_L = 220 mm
ARM_A = 60 deg
UP_H = 140 mm
UP_PIVOT = T + UP_H - 25 mm      # the upright's pivot, from its tenons' tips

assembly lamp {
    solid base {
        disc = Circle(center=(0, 0), diameter=180 mm)
        upright = tab_and_slot(part="slot", length=50 mm, thickness=T, tabs=2, tab=15 mm, screw=0,
                               cx=0 mm, cy=0 mm)
        for k in range(4) {
            hole weight { c = Circle(center=polar((0, 0), 55 mm, 45 deg + k * 90 deg), diameter=4.5 mm) }
        }
        Countersink(weight, diameter=9 mm)
    }

    # drawn standing: y up from the tenons' tips (the base's underside)
    solid upright {
        post = Rectangle(bottom_left=(-25 mm, 0), width=50 mm, height=UP_PIVOT)
        round = Circle(center=(0, UP_PIVOT), radius=25 mm)
        foot = tab_and_slot(part="tab", length=50 mm, thickness=T, tabs=2, tab=15 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=0 mm)
        hole pivot { c = Circle(center=(0, UP_PIVOT), diameter=PIVOT) }
        hole jack { c = Circle(center=(0, T + 30 mm), diameter=8 mm) }
        hole switch { r = Rectangle(center=(0, T + 70 mm), width=13 mm, height=19 mm) }
        hole cable { c = Circle(center=(0, T + 94 mm), diameter=6 mm) }
        drawing marks {
            dc = Text("5V DC", position=(0, T + 18 mm), size=4 mm)
            on = Text("I", position=(0, T + 82 mm), size=4 mm)
            off = Text("O", position=(0, T + 54 mm), size=4 mm)
        }
    }

    solid arm {
        bar = Slot(start=(0, 0), end=(ARM_L, 0), width=30 mm)
        hole low { c = Circle(center=(0, 0), diameter=PIVOT) }
        hole high { c = Circle(center=(ARM_L, 0), diameter=PIVOT) }
        for x in [60 mm, 110 mm, 160 mm] {
            hole tie {
                a = Slot(center=(x, 6 mm), length=5 mm, width=2.5 mm)
                b = Slot(center=(x, -6 mm), length=5 mm, width=2.5 mm)
            }
        }
    }

    # drawn standing: y up from the tenon's tip (the head's underside)
    solid ear {
        post = Rectangle(bottom_left=(-20 mm, 0), width=40 mm, height=26 mm)
        round = Circle(center=(0, 26 mm), radius=20 mm)
        foot = tab_and_slot(part="tab", length=40 mm, thickness=T, tabs=1, tab=20 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=0 mm)
        hole pivot { c = Circle(center=(0, 26 mm), diameter=PIVOT) }
    }

    solid head {
        plate = RoundedRectangle(center=(0, 0), width=220 mm, height=50 mm, corner_radius=10 mm)
        # FIX after the first valid program: the plate ran back under the arm (W0517); the ear now
        # stands 15 mm off the plate's centre line, on an 8 mm spacer in front of the arm,
        # so the plate lies clear in front of the arm's plane
        ear = tab_and_slot(part="slot", length=40 mm, thickness=T, tabs=1, tab=20 mm, screw=0,
                           cx=-70 mm, cy=15 mm)
        hole cable { c = Circle(center=(-52 mm, 15 mm), diameter=5 mm) }
        drawing name { t = Text("LUMEN", position=(40 mm, 0), size=10 mm, valign="middle") }
    }

    # flat, for cutting
    RightOf(upright, base, gap=10 mm)
    AlignBottom(upright, base)
    RightOf(ear, upright, gap=10 mm)
    AlignBottom(ear, base)
    Above(arm, base, gap=10 mm)
    AlignLeft(arm, base)
    Above(head, arm, gap=10 mm)
    AlignLeft(head, base)

    # assembled: the upright across the base's middle, the arm in front of it, the ear in front of the arm
    Place(base, position=(0, 0, 0), face="up")
    Place(upright, position=(0, T / 2, 0), face="front", up="up")
    Place(arm, position=(0, -T / 2, UP_PIVOT), face="front", up=(-sin(ARM_A), 0, cos(ARM_A)))
    Place(ear, position=(ARM_L * cos(ARM_A), -T / 2 - 8 mm - T, UP_PIVOT + ARM_L * sin(ARM_A) - 26 mm),
          face="front", up="up")
    Place(head, position=(ARM_L * cos(ARM_A) + 70 mm, -T / 2 - 8 mm - T - T / 2 - 15 mm, UP_PIVOT + ARM_L * sin(ARM_A) - 26 mm),
          face="up")

    assert base.disc.diameter == 180 mm, "base 180 across"
    assert len(base.weight) == 4, "four weight-plate screws"
    assert distance(base.weight[0].c.center, (0, 0)) == 55 mm, "on a 110 mm circle"
    assert upright.round.center.y - upright.post.bb.bottom == 6 mm + 140 mm - 25 mm, "upright 140 above the base"
    assert upright.switch.r.bb.width == 13 mm and upright.switch.r.bb.height == 19 mm, "KCD1 cut-out"
    assert upright.jack.c.diameter == 8 mm, "DC jack hole"
    assert arm.high.c.center.x - arm.low.c.center.x == 220 mm, "220 between the arm's pivots"
    assert len(arm.tie) == 3, "three zip-tie pairs"
    assert head.plate.bb.width == 220 mm and head.plate.bb.height == 50 mm, "head 220 x 50"
    assert ear.pivot.c.center.y - ear.post.bb.bottom == 26 mm, "pivot 26 above the head's underside"
    assert ear.round.bb.top - ear.pivot.c.center.y == 20 mm, "pivot 20 below the ear's top"
    assert head.ear.slot[0].bb.center_x - head.plate.bb.left == 40 mm, "ear 40 from the back end"
}
