# Request (workshop): a thin-rip jig for my table saw, cut from 12 mm birch ply. An arm
# 220 x 70 mm (5 mm corner radii) with a round-ended nose on its right end, 40 mm wide and
# reaching 40 mm past the arm (overall length 260 mm). The nose carries a 608 bearing on an
# M8 bolt: an 8.4 mm hole 20 mm in from the nose tip, with a 14 mm counterbore 6 mm deep for
# the socket head. Two M6 adjustment slots (6.5 mm wide, 60 mm long tip to tip) on the arm's
# centre line, their centres 70 mm apart, the right one's centre 40 mm from the arm's right
# end, bolt it to the mitre-slot bar. Above the right slot an engraved scale: a tick every
# 5 mm over 50 mm of travel (0 at the slot's left arc centre), long ticks every 10 mm,
# numbered 0-50 in 3.5 mm figures. "THIN RIP" engraved filled in 10 mm bold letters under
# the slots.

import "std/shapes.aidl"

thickness 12 mm

param arm_l = 220 mm, min = 180 mm, max = 300 mm
param arm_w = 70 mm, min = 60 mm, max = 100 mm
nose_w = 40 mm
nose_reach = 40 mm
slot_l = 60 mm
slot_w = 6.5 mm
slot_pitch = 70 mm

solid jig {
    arm = RoundedRectangle(center=(0, 0), width=arm_l, height=arm_w, corner_radius=5)
    nose = Slot(start=(arm_l / 2, 0), end=(arm_l / 2 + nose_reach - nose_w / 2, 0), width=nose_w)

    hole axle {
        c = Circle(center=(arm_l / 2 + nose_reach - 20, 0), diameter=8.4)
    }
    Counterbore(axle, diameter=14, depth=6)

    right_slot = slot_hole(length=slot_l, width=slot_w, cx=arm_l / 2 - 40, cy=0)
    left_slot = slot_hole(length=slot_l, width=slot_w, cx=arm_l / 2 - 40 - slot_pitch, cy=0)

    drawing scale {
        for i in range(11) {
            tick = Line((arm_l / 2 - 40 - slot_l / 2 + slot_w / 2 + i * 5, 6),
                        (arm_l / 2 - 40 - slot_l / 2 + slot_w / 2 + i * 5, 10 if i % 2 == 1 else 13))
        }
        for j in range(6) {
            num = Text(str(j * 10), position=(arm_l / 2 - 40 - slot_l / 2 + slot_w / 2 + j * 10, 15),
                       size=3.5)
        }
    }

    drawing name {
        t = Text("THIN RIP", position=(-arm_l / 2 + 75, -22), size=10, font="sans:Bold",
                 valign="middle", fill=true)
    }

    assert self.bb.width == 260 mm, "overall length 260 mm"
    assert nose.width == 40 mm
    assert distance(axle.c.center, nose.end) == 0 mm
    assert right_slot.s.center.x - left_slot.s.center.x == 70 mm
    assert arm.right.midpoint.x - right_slot.s.center.x == 40 mm
    assert len(scale.tick) == 11
    assert len(scale.num) == 6
    assert distance(name, left_slot) >= 3 mm
}
