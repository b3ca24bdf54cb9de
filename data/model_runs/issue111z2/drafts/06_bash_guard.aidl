# Sport (cycling): a bash guard for a 104 mm BCD crank, 6 mm sheet. A disc 170 mm across with
# an 80 mm central opening that clears the spider. Four 10.5 mm bolt holes on the 104 mm bolt
# circle at 45, 135, 225 and 315 deg, countersunk 16 mm (90 deg flat chainring bolts). Four
# lightening windows between the bolts: arc slots 12 mm wide on a 67 mm radius, each spanning
# 60 deg, centred at 0, 90, 180 and 270 deg. "BCD 104  MAX 36T" engraved along a 76 mm radius
# over the top, 5 mm stroke letters.

units mm
thickness 6 mm

param od = 170 mm, min = 150, max = 200

solid guard {
    disc = Circle(center=(0, 0), diameter=od)

    hole spider {
        c = Circle(center=(0, 0), diameter=80)
    }

    hole bolt {
        c = Circle(center=(52 * cos(45 deg), 52 * sin(45 deg)), diameter=10.5)
    }
    bolts = CircularPattern(bolt, 4, disc.center)
    Countersink(bolt, diameter=16)

    hole windows {
        for i in range(4) {
            w = ArcSlot(center=(0, 0), radius=67, start_angle=i * 90 - 30, end_angle=i * 90 + 30,
                        width=12)
        }
    }

    drawing label {
        ring = Circle(center=(0, 0), radius=76, construction=true)
        t = Text("BCD 104  MAX 36T", along=ring, size=5)
    }

    assert disc.diameter == 170 mm, "170 mm disc"
    assert spider.c.diameter == 80 mm, "80 mm central opening"
    assert len(bolts) == 4, "4 bolts"
    assert abs(distance(bolts[0].c.center, bolts[2].c.center) - 104 mm) < 0.001 mm, "104 mm BCD"
    assert bolt.c.diameter == 10.5 mm, "10.5 mm bolt holes"
    assert len(windows.w) == 4 and windows.w[0].width == 12 mm, "4 windows 12 mm wide"
}
