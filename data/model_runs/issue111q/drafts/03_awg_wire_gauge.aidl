# Electronics: a round AWG wire gauge, a 70 mm disc of 3 mm acrylic. Eight gauge slots
# round the rim, 45 deg apart starting at the top: AWG 10, 12, 14, 16, 18, 20, 22, 24 with
# widths 2.59, 2.05, 1.63, 1.29, 1.02, 0.81, 0.64, 0.51 mm, each 9 mm deep from the rim and
# ending in a relief hole 1.5 mm wider than its slot. Each slot's number engraved 3.5 mm high
# at radius 19 mm on the slot's line. A 6 mm keyring hole in the centre, "AWG" 5 mm below it.

thickness 3 mm

gauges = [10, 12, 14, 16, 18, 20, 22, 24]
widths = [2.59, 2.05, 1.63, 1.29, 1.02, 0.81, 0.64, 0.51]
R = 35 mm
depth = 9 mm

solid gauge {
    disc = Circle(center=(0, 0), diameter=70)

    hole slots {
        for i in range(8) {
            a = 90 deg - i * 45 deg
            slit = Rectangle(center=((R - depth / 2 + 0.5) * cos(a), (R - depth / 2 + 0.5) * sin(a)),
                             width=depth + 1, height=widths[i], rotation=a)
            relief = Circle(center=((R - depth) * cos(a), (R - depth) * sin(a)),
                            diameter=widths[i] + 1.5)
        }
    }

    hole ring {
        c = Circle(center=(0, 0), diameter=6)
    }

    drawing numbers {
        for i in range(8) {
            a = 90 deg - i * 45 deg
            n = Text(str(gauges[i]), (19 * cos(a), 19 * sin(a)), size=3.5, valign="middle")
        }
        title = Text("AWG", (0, -9), size=5, valign="middle")
    }

    assert disc.diameter == 70 mm, "disc 70 across"
    assert len(slots.slit) == 8, "eight gauges"
    assert slots.slit[0].height == 2.59 mm, "AWG 10 is 2.59"
    assert slots.slit[7].height == 0.51 mm, "AWG 24 is 0.51"
    assert ring.c.diameter == 6 mm, "keyring hole 6"
}
