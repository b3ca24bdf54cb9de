# Wall clock face: 200 mm disc, 12 engraved hour ticks, numerals 1-12 inside the ticks,
# 7.5 mm centre hole for the movement shaft.

param dia = 200 mm
param tick_len = 12 mm
param tick_outer = 92 mm     # radius of the tick's outer end
param num_r = 68 mm          # radius of numeral centres
param num_size = 12 mm

solid face {
    disc = Circle(center=(0, 0), diameter=dia)
    Fixed(disc)

    hole shaft {
        c = Circle(center=(0, 0), diameter=7.5)
    }
    Concentric(shaft.c, disc)

    drawing ticks {
        for i in range(12) {
            t = Line(start=(tick_outer * cos(i * 30 deg), tick_outer * sin(i * 30 deg)),
                     end=((tick_outer - tick_len) * cos(i * 30 deg), (tick_outer - tick_len) * sin(i * 30 deg)))
        }
    }
    Rigid(ticks)
    CenterInside(ticks, disc)

    drawing numerals {
        for h in range(1, 13) {
            n = Text(str(h), position=(num_r * sin(h * 30 deg), num_r * cos(h * 30 deg)),
                     size=num_size, valign="middle")
        }
    }
    Rigid(numerals)
    CenterInside(numerals, disc)
}
