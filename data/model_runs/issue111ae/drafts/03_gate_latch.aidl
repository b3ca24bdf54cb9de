# Request (garden): a gravity latch for a garden gate, cut from 6 mm HDPE, three parts.
# - Latch bar 200 x 25 mm, its pivot end fully rounded (R12.5), its nose corners R4; an M6
#   pivot hole 15 mm from the pivot end, on the bar's centre line; a thumb lift: a round-ended
#   tab 18 mm wide standing 22 mm above the bar's top edge, its centre 40 mm from the nose,
#   joined with R3 fillets; "CLOSE THE GATE" engraved (serif outlines, 7 mm) along the bar
#   between the pivot and the lift.
# - Keeper for the post: 70 mm wide, a 27 mm wide notch (bar + 2 mm) 35 mm deep whose floor is
#   65 mm above the keeper's bottom; the horn on the gate side is a ramp rising from 70 mm at
#   the outer edge to 95 mm at the notch so the bar rides up and drops in; the far horn stands
#   110 mm tall as the stop. Corners rounded R3 (horn tops R5). Three countersunk M4 screw holes
#   (8 mm heads): two at 20 mm up, 15 mm in from each side, one centred 45 mm up.
# - A 30 mm washer with an M6 hole to go under the pivot bolt's head.
# (FIX after the first valid program: the keeper above cannot work, see the keeper; it is now
#  a 60 x 100 R3 post plate, 3 countersunk M4 holes, with a hook plate standing out of it on a
#  16 mm tenon, and the washer goes between the gate and the bar as a 6 mm spacer.)

units mm
thickness 6 mm
import "std/fasteners.aidl"
import "std/joints.aidl"

param bar_len = 200 mm, min = 150 mm, max = 300 mm
param bar_h = 25 mm, min = 20 mm, max = 35 mm

assembly gate_latch {
    solid bar {
        body = RoundedRectangle(center=(0, 0), width=bar_len, height=bar_h,
                                corner_radii=[bar_h / 2, 4, 4, bar_h / 2])
        lift = Slot(center=(bar_len / 2 - 40, bar_h / 2), length=2 * 22, width=18,
                    rotation=90)
        Fillet([lift, body], 3)
        pivot = clearance_hole(size=6)
        pivot.c.center == (body.bb.left + 15, body.center.y)
        drawing words {
            w = Text("CLOSE THE GATE", position=(0, 0), size=7, font="serif",
                     valign="middle")
        }
        AlignCenterY(words, body)
        # centred between the pivot hole and the lift tab
        words.bb.center_x == (pivot.c.center.x + lift.bb.left) / 2
    }

    # FIX after the first valid program: the requested keeper had its notch in the bar's own
    # plane, so a bar resting in the notch would run through the ramp horn: a gate swings the
    # bar's nose toward the post, across the bar's plane. The keeper is now a post plate and a
    # hook plate standing out of it on a tenon; the hook's notch is 8 mm wide (the 6 mm bar
    # spaced 6 mm off the gate by the washer, + 2 mm), its ramp rises from the outer end.
    solid keeper {
        outline = RoundedRectangle(center=(0, 0), width=60, height=100, corner_radius=3)
        hole screws {
            a = Circle(center=(-15, -38), diameter=4.5)
            b = Circle(center=(15, -38), diameter=4.5)
            c = Circle(center=(0, -20), diameter=4.5)
        }
        Countersink(screws, diameter=8)
        # the hook's tenon: its 30 mm foot stands vertical on the plate's centre line,
        # from 40 to 70 mm above the plate's bottom
        mortise = tab_and_slot(part="slot", length=30, thickness=6, tabs=1, tab=16, screw=0,
                               rotation=90, cx=0, cy=-50 + 55)
    }

    solid hook {
        # x: out from the post plate's face (the tenon behind x = 0), y: up from the foot
        outline = Polygon([(-6, 0), (45, 0), (45, 28), (8, 62), (8, 30), (-6, 30)])
        Fillet([outline.points[1], outline.points[2]], 3)
        Fillet(outline.points[3], 2)
        tenon = tab_and_slot(part="tab", length=30, thickness=6, tabs=1, tab=16, screw=0,
                             rotation=90, cx=-6, cy=15)
    }

    solid washer {
        ring = Circle(center=(0, 0), diameter=30)
        bolt = clearance_hole(size=6)
        Concentric(bolt.c, ring)
    }

    Fixed(bar)
    RightOf(keeper, bar, gap=15)
    AlignBottom(keeper, bar)
    RightOf(hook, keeper, gap=15)
    AlignBottom(hook, keeper)
    Below(washer, bar, gap=15)
    AlignLeft(washer, bar)

    # the request's numbers
    assert bar.body.bb.width == 200 mm and bar.body.bb.height == 25 mm, "bar 200 x 25"
    assert bar.pivot.c.center.x - bar.body.bb.left == 15 mm, "pivot 15 mm from the end"
    assert abs(bar.lift.bb.top - bar.body.bb.top - 22 mm) < 0.01 mm, "lift 22 mm above the bar"
    assert abs(bar.body.bb.right - bar.lift.center.x - 40 mm) < 0.01 mm, "lift 40 mm from nose"
    assert hook.outline.points[3].x - hook.outline.points[4].x == 0, "notch wall upright"
    assert hook.outline.points[4].x - (hook.outline.points[0].x + 6 mm) == 6 mm + 2 mm, "notch: 6 mm bar + 2 mm"
    assert hook.outline.points[3].y - hook.outline.points[4].y > bar_h, "horn above the bar"
    assert bar.words.bb.right < bar.lift.bb.left - 3 mm, "the words clear the lift"
}
