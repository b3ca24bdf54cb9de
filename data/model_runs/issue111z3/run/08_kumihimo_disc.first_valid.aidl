# Crafts: kumihimo braiding disc, 150 mm across, cut from 2 mm polypropylene sheet. 32 radial slits
# (laser cut lines, which grip the threads) evenly round the rim, each running 15 mm in from the
# edge and ending in a 1.5 mm relief hole; slit 1 points straight up, the others follow clockwise.
# A 12 mm hole in the centre for the braid. Each slit numbered 1 to 32 in engraved strokes 4 mm
# high, upright, the numbers' middle on a 54 mm radius in line with their slit.

units mm
thickness 2 mm

param dia = 150 mm, min = 100, max = 200
param slits = 32, min = 8, max = 32
param slit_len = 15 mm, min = 8, max = 20

def ang(i) = 90 deg - i * 360 deg / slits

solid disc {
    body = Circle(center=(0, 0), diameter=dia)

    hole braid {
        c = Circle(center=(0, 0), diameter=12)
    }

    cut slit {
        for i in range(slits) {
            # from the relief hole out to 1 mm past the rim, so the slit opens cleanly
            l = Line(polar((0, 0), dia / 2 - slit_len, ang(i)), polar((0, 0), dia / 2 + 1, ang(i)))
        }
    }

    hole relief {
        for i in range(slits) {
            c = Circle(center=polar((0, 0), dia / 2 - slit_len, ang(i)), diameter=1.5)
        }
    }

    drawing numbers {
        track = Circle(center=(0, 0), radius=54, construction=true)
        for i in range(slits) {
            t = Text(str(i + 1), along=track, angle=ang(i), size=4, valign="middle")
        }
    }

    assert body.diameter == 150 mm, "150 mm disc"
    assert len(slit.l) == 32 and len(relief.c) == 32, "32 slits, 32 relief holes"
    assert distance(slit.l[0].start, body.center) == 75 mm - 15 mm, "slits 15 mm in from the rim"
    assert relief.c[0].diameter == 1.5 mm, "1.5 mm relief holes"
    assert slit.l[0].start.x == 0 and slit.l[0].start.y > 0, "slit 1 straight up"
    assert slit.l[8].start.x > 0 and abs(slit.l[8].start.y) < 0.001, "slit 9 at 3 o'clock: clockwise"
    assert braid.c.diameter == 12 mm, "12 mm centre hole"
    assert numbers.t[0].size == 4 mm, "numbers 4 high"
    assert len(numbers.t) == 32, "32 numbers"
}
