# Request: a replacement scale for an 85C1-style moving-coil panel meter, re-marked 0-30 V DC
# for my bench power supply. Cut from 1.5 mm white acrylic, the scale engraved.
# Plate 64 x 44 mm, its two top corners rounded R3. The needle's pivot is on the plate's
# centre line 6 mm above its bottom edge; a 7 mm wide round-topped notch rises 10 mm from the
# bottom edge to clear the pivot boss. Two 2.2 mm mounting holes, 52 mm apart, 5 mm above
# the bottom edge. The scale: a 90 degree arc of radius 32 mm about the pivot (45 to 135
# degrees), 0 V at the left end; 31 ticks (0 to 30 V, one per volt) outward from the arc,
# 4 mm long every 5 V, 2 mm otherwise; the numbers 0, 5, ... 30, 3 mm tall, upright, centred
# on radius 27 mm; "V" 5 mm tall and "DC" 2.5 mm tall on the centre line, 16 mm and 9.5 mm
# above the pivot.

units mm
thickness 1.5 mm
kerf 0.1 mm

W = 64 mm
H = 44 mm
pivot_y = 6 mm       # above the bottom edge
R = 32 mm            # scale arc radius
volts = 30
def ang(v) = 135 deg - v * (90 deg / volts)

solid meter_scale {
    body = RoundedRectangle(center=(0, H / 2), width=W, height=H, corner_radii=[3, 3, 0, 0])

    hole notch {
        s = Slot(start=(0, -6), end=(0, 10 - 3.5), width=7, overrun=true)
    }
    hole mount {
        for sx in [-1, 1] {
            c = Circle(center=(sx * 52 / 2, 5), diameter=2.2)
        }
    }

    drawing scale {
        pv = Point(0, pivot_y, construction=true)
        arc = Arc(center=(0, pivot_y), radius=R, start_angle=45 deg, end_angle=135 deg)
        for v in range(volts + 1) {
            tick = Line(start=polar(pv, R, ang(v)), end=polar(pv, R + (4 if v % 5 == 0 else 2), ang(v)))
        }
        for k in range(7) {
            num = Text(str(5 * k), position=polar(pv, 27, ang(5 * k)), size=3, valign="middle")
        }
        unit = Text("V", position=(0, pivot_y + 16), size=5, valign="middle")
        dc = Text("DC", position=(0, pivot_y + 9.5), size=2.5, valign="middle")
    }
    Fixed(body)

    assert body.bb.width == 64 mm and body.bb.height == 44 mm, "plate 64 x 44"
    assert mount.c[1].center.x - mount.c[0].center.x == 52 mm, "holes 52 mm apart"
    assert mount.c[0].center.y - body.bb.bottom == 5 mm, "holes 5 mm above the bottom edge"
    assert mount.c[0].diameter == 2.2 mm
    assert notch.s.bb.top - body.bb.bottom == 10 mm, "notch rises 10 mm"
    assert notch.s.width == 7 mm
    assert scale.pv.y - body.bb.bottom == 6 mm, "pivot 6 mm above the bottom edge"
    assert scale.arc.radius == 32 mm
    assert len(scale.tick) == 31, "one tick per volt, 0 to 30"
    assert scale.tick[5].length == 4 mm and scale.tick[6].length == 2 mm, "major / minor ticks"
    assert len(scale.num) == 7
    assert scale.tick[0].start.x < 0 and scale.tick[30].start.x > 0, "0 V at the left"
    assert scale.bb.top <= body.bb.top - 1 mm, "ticks clear of the top edge"
    assert distance(scale.num, notch) >= 1 mm and distance(scale.dc, notch) >= 1 mm
}
