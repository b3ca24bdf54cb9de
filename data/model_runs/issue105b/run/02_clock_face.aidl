# Wall clock face: a disc 250 mm in diameter (3 mm plywood) with an 8 mm center
# hole for the clock movement's spindle, 60 engraved minute ticks (4 mm long) and
# 12 hour ticks (12 mm long) reaching in from 6 mm inside the rim, and the
# numerals 1-12 engraved upright, 12 mm tall, centered on a circle of radius 92 mm.

units mm
thickness 3 mm

param d = 250 mm, min = 150 mm, max = 400 mm
param numeral_size = 12 mm, min = 6 mm, max = 20 mm

R = d / 2

solid face {
    disc = Circle(center=(0, 0), diameter=d)
    hole spindle {
        c = Circle(center=(0, 0), diameter=8)
    }
    Concentric(spindle.c, disc)

    drawing ticks {
        for h in range(12) {
            hour = Line(start=(0, R - 18), end=(0, R - 6), construction=false)
        }
        for m in range(60) {
            if m % 5 != 0 {
                minute = Line(start=(0, R - 10), end=(0, R - 6))
            }
        }
    }

    drawing numerals {
        for h in range(1, 13) {
            n = Text(str(h), position=(0, 0), size=numeral_size, valign="middle")
        }
    }

    # place the ticks and numerals round the disc's center
    for h in range(12) {
        Coincident(ticks.hour[h].start, polar(disc.center, R - 18, 90 deg - h * 30 deg))
        Coincident(ticks.hour[h].end, polar(disc.center, R - 6, 90 deg - h * 30 deg))
        Coincident(numerals.n[h].position, polar(disc.center, R - 33, 90 deg - (h + 1) * 30 deg))
    }
    for k in range(48) {
        m = k + 1 + k // 4
        Coincident(ticks.minute[k].start, polar(disc.center, R - 10, 90 deg - m * 6 deg))
        Coincident(ticks.minute[k].end, polar(disc.center, R - 6, 90 deg - m * 6 deg))
    }
}
