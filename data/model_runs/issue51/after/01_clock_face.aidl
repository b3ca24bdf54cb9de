# A wall clock face: 200 mm disc, 12 engraved hour ticks (loop),
# hour numerals 1-12 engraved inside the ticks, 7.5 mm centre hole.

param dia = 200 mm
param tick_outer = 94 mm
param tick_inner = 84 mm
param numeral_r = 72 mm
param numeral_size = 12 mm

solid clock {
    face = Circle(center=(0, 0), diameter=dia)
    Fixed(face)

    hole shaft {
        c = Circle(center=(0, 0), diameter=7.5)
    }
    Concentric(shaft.c, face)

    drawing ticks {
        for i in range(12) {
            t = Line((tick_inner * cos(i * 30 deg), tick_inner * sin(i * 30 deg)),
                     (tick_outer * cos(i * 30 deg), tick_outer * sin(i * 30 deg)))
        }
    }

    drawing numerals {
        for h in range(1, 13) {
            n = Text(str(h), position=(numeral_r * sin(h * 30 deg), numeral_r * cos(h * 30 deg)),
                     size=numeral_size, valign="middle")
        }
    }
}
