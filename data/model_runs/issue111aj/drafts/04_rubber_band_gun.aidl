# Request (toys): a single-shot rubber-band pistol from 6 mm ply, four parts.
# Body: a barrel 220 x 20 mm with a V notch 6 mm wide and 6 mm deep in its top, 7 mm from
# the muzzle end, to hold the band; a pistol grip 32 x 95 mm (corners R10) leaning back
# 15 deg, its centre 30 mm from the barrel's rear end and 38 mm below the barrel's bottom
# edge; a trigger guard, a 6 mm band along an arc from the grip's front down under the
# trigger and up into the barrel 105 mm from the rear; a 4.2 mm pivot hole (M4 bolt) 75 mm
# from the rear, in the middle of the barrel's height; engraved "NEVER AIM AT FACES" on the
# barrel. Trigger: a hub R8 round a 4.4 mm pivot hole, a catch 9 mm wide rising 24 mm above
# the pivot with a hook 9 mm long pointing back at its top (the band loops behind it), and a
# finger lever 10 mm wide reaching 32 mm below the pivot. Two spacer washers 14 mm outside,
# 4.4 mm bore, for the bolt.
#
# FIX after the first valid program (two things):
# 1. W0515 (the window enclosed by barrel, grip and guard) is the finger opening the request
#    asks for: a false alarm, accepted with the AllowOverlap the hint gives.
# 2. A defect no message could name, my own design slip: with the catch above the pivot the
#    band's pull turns the trigger the way a finger does, so it fires by itself (no sear).
#    Redesigned: the pivot sits in a hump 31 mm above the barrel's bottom (the request's
#    "75 mm from the rear" becomes 80), the band sits in an up-turned hook 9 mm BELOW the
#    pivot (2 mm above the barrel), so the band's pull turns the trigger forward against a
#    4 mm stop pin; pulling the lever (57 mm long now) tips the hook and lets the band go.

import "std/shapes.aidl"

thickness 6 mm

param barrel_len = 220 mm, min = 150 mm, max = 300 mm
barrel_h = 20 mm
pivot_x = 80 mm
pivot_y = 31 mm

assembly band_gun {
    solid body {
        barrel = Rectangle(bottom_left=(0, 0), width=barrel_len, height=barrel_h)
        hump = RoundedRectangle(bottom_left=(pivot_x - 18, 10), width=36, height=30,
                                corner_radii=[8, 8, 0, 0])
        grip = RoundedRectangle(center=(30, -38), width=32, height=95, corner_radius=10,
                                rotation=-15 deg)
        guard_path = Arc(start=(44, -45), through=(75, -40), end=(105, 2), construction=true)
        guard = Stroke(guard_path, width=6)
        AllowOverlap(barrel, grip, guard)
        hole muzzle {
            v = Polygon([(barrel_len - 10, barrel_h + 1), (barrel_len - 4, barrel_h + 1),
                         (barrel_len - 7, barrel_h - 6)], overrun=true)
        }
        hole pivot {
            c = Circle(center=(pivot_x, pivot_y), diameter=4.2)
        }
        hole stop_pin {
            c = Circle(center=(pivot_x + 9, pivot_y - 26), diameter=4)
        }
        drawing warn {
            t = Text("NEVER AIM AT FACES", position=(150, barrel_h / 2), size=4, valign="middle")
        }
        assert barrel.bb.width == 220 mm and barrel.bb.height == 20 mm, "barrel 220 x 20"
        assert barrel.bb.right - muzzle.v.points[2].x == 7 mm, "band notch 7 mm from the muzzle"
    }

    solid trigger {
        hub = Circle(center=(0, 0), radius=8)
        lever = Slot(start=(0, 0), end=(3, -52), width=10)
        # up-turned hook in front of the lever: the band lies on its floor (y = -9)
        hook = Polygon([(4, -12), (12, -12), (12, -4), (9, -4), (9, -9), (4, -9)])
        hole pivot {
            c = Circle(center=(0, 0), diameter=4.4)
        }
    }

    w1 = washer(outer=14 mm, inner=4.4 mm)
    w2 = washer(outer=14 mm, inner=4.4 mm)

    RightOf(trigger, body, gap=10)
    AlignTop(trigger, body)
    Below(w1, trigger, gap=8)
    AlignLeft(w1, trigger)
    RightOf(w2, w1, gap=6)
    AlignTop(w2, w1)

    # assembled: the band seat is below the pivot (so the band holds the trigger forward)
    # and above the barrel's top (so the band clears the barrel)
    seat = pivot_y - 9 mm
    assert seat < pivot_y and seat - barrel_h == 2 mm, "band seat 9 mm below the pivot"
    # the stop pin sits just in front of the lever
    assert body.stop_pin.c.center.x - body.pivot.c.center.x - 2 mm > 5 mm + 3 mm * 26 / 52,
        "the stop pin clears the resting lever"
    # the lever clears the guard (guard's top edge 37 mm below the barrel's bottom at x 75)
    assert pivot_y - (trigger.pivot.c.center.y - trigger.lever.bb.bottom) > -37 mm + 8 mm,
        "the lever clears the guard"
}
