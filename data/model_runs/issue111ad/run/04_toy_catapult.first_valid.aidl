# Toys: a tabletop catapult kit for my nephew, 3 mm plywood, 5 parts.
# Base 180 x 70 mm, corners R6, with the mortises for two uprights (each 2 glued
# tabs 15 mm wide along the uprights' 70 mm foot), the uprights' centre planes
# 12 mm either side of the base's centre line and their middles 40 mm right of
# the base's centre; a 12 x 4 mm slot for the rubber band 75 mm right of the
# centre; "CATAPULT" engraved in serif outline letters, 8 mm high, centred 45 mm
# left of the base's centre.
# Two uprights: trapezoids 70 mm at the foot, 20 mm at the top, 90 mm tall, a
# 6.3 mm axle hole 15 mm left of the middle and 25 mm above the shoulder, a
# halving slot 5 deep at the top middle for the stop bar.
# Stop bar 45 x 10 mm halved 5 deep from below where the uprights cross it.
# Arm: 14 mm wide, the pivot hole (6.3 mm) 140 mm from the centre of a ring cup
# 34 mm across with a 24 mm well, a 4 mm rubber-band hole 45 mm from the pivot.

import "std/joints.aidl"

units mm
thickness 3 mm

param t = 3 mm, min = 2, max = 4
param arm_len = 140 mm, min = 100, max = 170
param axle = 6.3 mm, min = 4, max = 8

def upright(t=3 mm, axle=6.3 mm) -> solid {
    body = Polygon([(-35, 0), (35, 0), (10, 90), (-10, 90)])
    feet = tab_and_slot(part="tab", length=70 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    hole pivot {
        c = Circle(center=(-15, 25 + t), diameter=axle)
    }
    top = cross_halving(depth=5 mm, thickness=t, cx=0 mm, cy=90 mm)
}

assembly catapult {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=180, height=70, corner_radius=6)
        left_mortise = tab_and_slot(part="slot", length=70 mm, thickness=t, tabs=2, tab=15 mm,
                                    screw=0, cx=40 mm, cy=12 mm)
        right_mortise = tab_and_slot(part="slot", length=70 mm, thickness=t, tabs=2, tab=15 mm,
                                     screw=0, cx=40 mm, cy=-12 mm)
        hole band {
            s = Slot(center=(75, 0), length=12, width=4, rotation=90)
        }
        drawing name {
            word = Text("CATAPULT", position=(-45, 0), size=8, valign="middle", font="serif")
        }
        assert plate.bb.width == 180 mm and plate.bb.height == 70 mm, "base 180 x 70"
        assert band.s.center.x - plate.bb.center_x == 75 mm, "band slot 75 right of centre"
        assert name.word.position.x - plate.bb.center_x == -45 mm, "name 45 left of centre"
    }

    post_a = upright(t=t, axle=axle)
    post_b = upright(t=t, axle=axle)

    solid stop {
        bar = Rectangle(center=(0, 0), width=45, height=10)
        h1 = cross_halving(depth=5 mm, thickness=t, rotation=180 deg, cx=-12 mm, cy=-5 mm)
        h2 = cross_halving(depth=5 mm, thickness=t, rotation=180 deg, cx=12 mm, cy=-5 mm)
    }

    solid arm {
        beam = Slot(start=(0, 0), end=(arm_len - 10 mm, 0), width=14)
        cup = Circle(center=(arm_len, 0), diameter=34)
        hole pivot {
            c = Circle(center=(0, 0), diameter=axle)
        }
        hole well {
            c = Circle(center=(arm_len, 0), diameter=24)
        }
        hole band {
            c = Circle(center=(45, 0), diameter=4)
        }
        assert well.c.center.x - pivot.c.center.x == 140 mm, "pivot 140 from the cup"
        assert band.c.center.x - pivot.c.center.x == 45 mm, "band hole 45 from the pivot"
    }

    RightOf(post_a, base, gap=10)
    AlignBottom(post_a, base)
    RightOf(post_b, post_a, gap=5)
    AlignBottom(post_b, base)
    Below(arm, base, gap=10)
    AlignLeft(arm, base)
    Below(stop, post_a, gap=10)
    AlignLeft(stop, post_a)

    assert post_a.body.bb.height == 90 mm, "uprights 90 tall"
    assert post_a.pivot.c.center.y - post_a.body.bb.bottom == 25 mm + t, "axle 25 above the shoulder"
}
