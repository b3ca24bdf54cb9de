# Science: a classroom star-wheel date disc, 3 mm white acrylic. Disc 150 mm across with a
# 3.2 mm rivet hole in the middle. Engraved: a circle 144 mm across; 12 month ticks from 62 to
# 72 mm out, the first straight up, going clockwise 30 degrees apart; between them 24 short ticks
# (every 10 degrees that is not a month tick) from 68 to 72 mm out; the 12 month names
# (JAN ... DEC, 4 mm letters) along a 116 mm circle, each centred in its 30-degree month, JAN
# first clockwise from the top. The Big Dipper's seven stars as 2.5 mm holes (Alkaid at
# (-40, 30), Mizar (-28, 36), Alioth (-17, 35), Megrez (-6, 32), Phecda (-4, 20), Merak
# (12, 18), Dubhe (14, 32)).

thickness 3 mm

months = ["JAN", "FEB", "MAR", "APR", "MAY", "JUN", "JUL", "AUG", "SEP", "OCT", "NOV", "DEC"]
stars = [(-40, 30), (-28, 36), (-17, 35), (-6, 32), (-4, 20), (12, 18), (14, 32)]

solid wheel {
    disc = Circle(center=(0, 0), diameter=150)

    hole rivet {
        c = Circle(center=(0, 0), diameter=3.2)
    }

    hole dipper {
        for i in range(7) {
            s = Circle(center=stars[i], diameter=2.5)
        }
    }

    drawing scale {
        o = Point(0, 0, construction=true)
        rim = Circle(center=(0, 0), diameter=144)
        for i in range(12) {
            tick = Line(polar(o, 62, 90 deg - i * 30 deg), polar(o, 72, 90 deg - i * 30 deg))
        }
        for j in range(36) {
            if j % 3 != 0 {
                short = Line(polar(o, 68, 90 deg - j * 10 deg), polar(o, 72, 90 deg - j * 10 deg))
            }
        }
        ring = Circle(center=(0, 0), diameter=116, construction=true)
        for i in range(12) {
            m = Text(months[i], along=ring, angle=90 deg - (i * 30 deg + 15 deg), size=4)
        }
    }
    Concentric(scale.o, disc)

    assert disc.diameter == 150 mm, "150 mm disc"
    assert rivet.c.diameter == 3.2 mm, "rivet 3.2"
    assert len(scale.tick) == 12, "12 month ticks"
    assert len(scale.short) == 24, "24 short ticks"
    assert len(scale.m) == 12, "12 months"
    assert len(dipper.s) == 7, "seven stars"
    assert scale.rim.diameter == 144 mm, "border 144"
}
