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

import "std/shapes.aidl"

thickness 6 mm

param barrel_len = 220 mm, min = 150 mm, max = 300 mm
barrel_h = 20 mm
pivot_x = 75 mm

assembly band_gun {
    solid body {
        barrel = Rectangle(bottom_left=(0, 0), width=barrel_len, height=barrel_h)
        grip = RoundedRectangle(center=(30, -38), width=32, height=95, corner_radius=10,
                                rotation=-15 deg)
        guard_path = Arc(start=(44, -45), through=(75, -40), end=(105, 2), construction=true)
        guard = Stroke(guard_path, width=6)
        hole muzzle {
            v = Polygon([(barrel_len - 10, barrel_h + 1), (barrel_len - 4, barrel_h + 1),
                         (barrel_len - 7, barrel_h - 6)], overrun=true)
        }
        hole pivot {
            c = Circle(center=(pivot_x, barrel_h / 2), diameter=4.2)
        }
        drawing warn {
            t = Text("NEVER AIM AT FACES", position=(150, barrel_h / 2), size=4, valign="middle")
        }
        assert barrel.bb.width == 220 mm and barrel.bb.height == 20 mm, "barrel 220 x 20"
        assert pivot.c.center.x - barrel.bb.left == 75 mm, "pivot 75 mm from the rear"
        assert barrel.bb.right - muzzle.v.points[2].x == 7 mm, "band notch 7 mm from the muzzle"
    }

    solid trigger {
        hub = Circle(center=(0, 0), radius=8)
        catch = Rectangle(bottom_left=(-4.5, 0), width=9, height=24)
        hook = Rectangle(bottom_left=(-13.5, 19), width=9, height=5)
        lever = Slot(start=(0, 0), end=(4, -32), width=10)
        hole pivot {
            c = Circle(center=(0, 0), diameter=4.4)
        }
        assert catch.bb.top - pivot.c.center.y == 24 mm, "catch rises 24 mm above the pivot"
    }

    w1 = washer(outer=14 mm, inner=4.4 mm)
    w2 = washer(outer=14 mm, inner=4.4 mm)

    RightOf(trigger, body, gap=10)
    AlignTop(trigger, body)
    Below(w1, trigger, gap=8)
    AlignLeft(w1, trigger)
    RightOf(w2, w1, gap=6)
    AlignTop(w2, w1)

    # assembled, the catch must stand at least 10 mm proud of the barrel's top to hold a band
    assert (trigger.catch.bb.top - trigger.pivot.c.center.y) -
           (body.barrel.bb.top - body.pivot.c.center.y) >= 10 mm, "the catch stands proud"
    # and the finger lever must clear the guard (guard's top edge at the pivot's x is below it)
    assert trigger.pivot.c.center.y - trigger.lever.bb.bottom < body.pivot.c.center.y - (-40 mm + 3 mm),
        "the trigger clears the guard"
}
