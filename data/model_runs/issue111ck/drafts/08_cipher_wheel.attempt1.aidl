# Request (gifts): a Caesar cipher wheel for a 9-year-old's birthday, in 3 mm plywood, two discs
# turning on a 5 mm Chicago screw (5.2 mm holes in both centres). The outer disc is 120 mm
# across with the 26 letters A-Z engraved round its rim, 7 mm tall, upright (their tops
# outward), middles on a 52 mm radius, A at the top and running clockwise; engraved ticks
# between the letters from 46 to 59 mm out. The inner disc is 90 mm across with A-Z 6 mm tall
# on a 39 mm radius, the same way round, and ticks between them from 34 to 44 mm out. On the
# inner disc "SECRET DECODER" is engraved 4 mm tall over the top and "AGENT MAX" under the
# bottom, both readable, on a 24 mm circle. Assembled, the inner disc lies on the outer one.

thickness 3 mm

letters = ["A", "B", "C", "D", "E", "F", "G", "H", "I", "J", "K", "L", "M",
           "N", "O", "P", "Q", "R", "S", "T", "U", "V", "W", "X", "Y", "Z"]
step = 360 deg / 26
screw_hole = 5.2 mm

assembly cipher_wheel {
    solid outer {
        disc = Circle(center=(0, 0), diameter=120)
        hole pivot {
            c = Circle(center=(0, 0), diameter=screw_hole)
        }
        drawing alphabet {
            ring = Circle(center=(0, 0), radius=52, construction=true)
            for i in range(26) {
                ch = Text(letters[i], along=ring, angle=90 deg - i * step, size=7,
                          valign="middle")
            }
        }
        drawing tick {
            l = Line(polar(disc.center, 46, 90 deg + step / 2),
                     polar(disc.center, 59, 90 deg + step / 2))
        }
        ticks = CircularPattern(tick, 26, disc.center)
    }

    solid inner {
        disc = Circle(center=(0, 0), diameter=90)
        hole pivot {
            c = Circle(center=(0, 0), diameter=screw_hole)
        }
        drawing alphabet {
            ring = Circle(center=(0, 0), radius=39, construction=true)
            for i in range(26) {
                ch = Text(letters[i], along=ring, angle=90 deg - i * step, size=6,
                          valign="middle")
            }
        }
        drawing tick {
            l = Line(polar(disc.center, 34, 90 deg + step / 2),
                     polar(disc.center, 44, 90 deg + step / 2))
        }
        ticks = CircularPattern(tick, 26, disc.center)
        drawing title {
            r = Circle(center=(0, 0), radius=24, construction=true)
            top = Text("SECRET DECODER", along=r, size=4)
            bottom = Text("AGENT MAX", along=r, size=4, flip=true)
        }
    }

    RightOf(inner, outer, gap=10)
    AlignCenterY(inner, outer)

    Place(outer, position=(0, 0, 0))
    Place(inner, position=(0, 0, 3))

    # the request's numbers
    assert outer.disc.diameter == 120 mm and inner.disc.diameter == 90 mm, "disc sizes"
    assert outer.pivot.c.diameter == 5.2 mm and inner.pivot.c.diameter == 5.2 mm, "5.2 mm holes"
    assert len(outer.alphabet.ch) == 26 and len(inner.alphabet.ch) == 26, "A-Z on both"
    assert outer.alphabet.ch[0].text == "A" and outer.alphabet.ch[25].text == "Z", "A to Z"
    assert len(outer.ticks) == 26 and len(inner.ticks) == 26, "a tick between each letter"
    assert outer.alphabet.ring.radius == 52 mm and inner.alphabet.ring.radius == 39 mm, "radii"
}
