# Request (home): a kitchen wall clock face cut from 4 mm birch plywood for a standard
# quartz clock movement. Face: a 280 mm disc with an 8 mm centre hole for the movement's
# shaft. 12 hour markers cut through as slots 18 mm long (radial), 4 mm wide, their outer
# ends 10 mm in from the rim; the four quarter markers (12, 3, 6, 9) are 6 mm wide.
# 48 minute ticks engraved as lines 6 mm long (radial), their outer ends 5 mm in from the
# rim, one every 6 degrees, skipping the hour positions. The numerals 12, 3, 6 and 9
# engraved filled, sans bold, 22 mm high, their centres 92 mm from the centre.
# "THE MILLERS" engraved in serif, 9 mm high, centred 50 mm below the centre.

units mm
thickness 4 mm

param face_d = 280 mm, min = 200 mm, max = 400 mm
mark_len = 18 mm
mark_in = 10 mm
r_mark = face_d / 2 - mark_in - mark_len / 2
tick_len = 6 mm
tick_in = 5 mm
r_num = 92 mm
def hour_angle(h) = 90 deg - h * 30 deg

solid clock {
    face = Circle(center=(0, 0), diameter=face_d)

    hole shaft {
        c = Circle(center=(0, 0), diameter=8)
    }

    hole hours {
        for h in range(12) {
            s = Slot(center=polar((0, 0), r_mark, hour_angle(h)), length=mark_len,
                     width=6 if h % 3 == 0 else 4, rotation=hour_angle(h))
        }
    }

    drawing minutes {
        for m in range(60) {
            if m % 5 != 0 {
                t = Line(polar((0, 0), face_d / 2 - tick_in - tick_len, 90 deg - m * 6 deg),
                         polar((0, 0), face_d / 2 - tick_in, 90 deg - m * 6 deg))
            }
        }
    }

    drawing numerals {
        for q in range(4) {
            n = Text(str(12 if q == 0 else q * 3), position=polar((0, 0), r_num, hour_angle(q * 3)),
                     size=22, font="sans:Bold", valign="middle", fill=true)
        }
    }

    drawing family {
        name = Text("THE MILLERS", position=(0, -50), size=9, font="serif", valign="middle")
    }

    Concentric(shaft.c, face)

    # the request's numbers
    assert face.diameter == 280 mm, "face 280 mm"
    assert shaft.c.diameter == 8 mm, "shaft hole 8 mm"
    assert len(hours.s) == 12, "12 hour markers"
    assert face.bb.top - hours.s[0].bb.top == 10 mm, "12 o'clock marker 10 mm in from the rim"
    assert hours.s[0].bb.height == 18 mm, "markers 18 mm long"
    assert hours.s[0].bb.width == 6 mm, "quarter markers 6 mm wide"
    assert hours.s[1].width == 4 mm, "other markers 4 mm wide"
    assert len(minutes.t) == 48, "48 minute ticks"
    assert len(numerals.n) == 4, "4 numerals"
    assert face.center.y - family.name.position.y == 50 mm, "name 50 mm below the centre"
}
