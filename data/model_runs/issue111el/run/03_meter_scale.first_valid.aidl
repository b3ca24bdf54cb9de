# Request: a new scale plate for an analog panel meter that I am turning into a 0-30 V
# voltmeter for my bench supply. 1 mm white acrylic, engraved. The plate is 80 wide; its
# bottom edge is 6 mm below the needle's pivot, its sides rise 30 mm above the pivot and
# its top is an arc of R50 about the pivot. A 10 mm wide slot open to the bottom edge with
# a round end on the pivot lets it slide in under the needle. Two M2 screw holes at
# +-30 mm, 5 mm above the pivot. The scale: an arc of R36 about the pivot over 90 degrees
# (0 V at the left), a tick per volt, 2.5 mm long, every 5 V a 5 mm tick with its number
# (3.5 mm) standing on R40. A big "V" (10 mm, bold, filled) 18 mm above the pivot.

import "std/fasteners.aidl"

units mm
thickness 1 mm

full = 30                 # volts at full scale
r_scale = 36 mm
r_num = 40 mm
def ang(v) = 135 deg - v * 90 deg / full

solid scale_plate {
    left_side = Line((-40, -6), (-40, 30))
    top = Arc(start=(-40, 30), through=(0, 50), end=(40, 30))
    right_side = Line((40, 30), (40, -6))
    bottom = Line((40, -6), (-40, -6))

    hole pivot {
        round = Circle(center=(0, 0), diameter=10)
        run = Rectangle(corner=(-5, -7), opposite=(5, 0), overrun=true)
    }
    left_screw = clearance_hole(size=2, cx=-30 mm, cy=5 mm)
    right_screw = clearance_hole(size=2, cx=30 mm, cy=5 mm)

    drawing scale {
        for v in range(full + 1) {
            tick = Line(((r_scale if v % 5 == 0 else r_scale) * cos(ang(v)), r_scale * sin(ang(v))),
                        ((r_scale + (5 mm if v % 5 == 0 else 2.5 mm)) * cos(ang(v)),
                         (r_scale + (5 mm if v % 5 == 0 else 2.5 mm)) * sin(ang(v))))
        }
        base_arc = Arc(center=(0, 0), radius=r_scale, start_angle=ang(full), end_angle=ang(0))
        ring = Circle(center=(0, 0), radius=r_num, construction=true)
        for k in range(full / 5 + 1) {
            n = Text(str(k * 5), along=ring, angle=ang(k * 5), size=3.5)
        }
    }
    drawing unit {
        u = Text("V", position=(0, 18), size=10, font="sans:Bold", valign="middle", fill=true)
    }

    assert len(scale.tick) == 31, "a tick per volt, 0 to 30"
    assert len(scale.n) == 7, "numbers every 5 V"
    assert top.radius == 50 mm, "top arc R50 about the pivot"
    assert top.center.x == pivot.round.center.x and top.center.y == pivot.round.center.y,
        "top arc about the pivot"
    assert pivot.round.center.y - bottom.start.y == 6 mm, "bottom edge 6 below the pivot"
    assert right_screw.c.center.x - left_screw.c.center.x == 60 mm, "screws at +-30"
    assert right_screw.c.center.y - pivot.round.center.y == 5 mm, "screws 5 above the pivot"
    assert distance(scale, top) >= 2 mm, "numbers clear of the top edge"
    assert distance(scale, right_side) >= 2 mm, "numbers clear of the side"
    assert distance(unit, scale) >= 2 mm, "V clear of the scale"
    assert distance(scale, left_screw) >= 1.5 mm, "scale clear of the screws"
}
