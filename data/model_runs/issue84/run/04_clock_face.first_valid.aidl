# A clock face: 200 mm disc, 8 mm hole for the movement's shaft, 60 minute
# ticks engraved (hour ticks 10 mm long, minute ticks 4 mm) and the numerals
# 1-12 engraved 20 mm inside the rim, 14 mm high.
param d = 200 mm

solid clock {
    disc = Circle(center=(0, 0), diameter=d)
    hole shaft { c = Circle(center=(0, 0), diameter=8) }
    drawing ticks {
        for i in range(60) {
            t = Line(polar((0, 0), d / 2 - 4 - (10 if i % 5 == 0 else 4), 90 deg - i * 6 deg),
                     polar((0, 0), d / 2 - 4, 90 deg - i * 6 deg))
        }
    }
    drawing numerals {
        for h in range(12) {
            n = Text(str(h + 1), polar((0, 0), d / 2 - 30, 90 deg - (h + 1) * 30 deg), size=14, valign="middle")
        }
    }
}
