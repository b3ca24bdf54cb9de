# Request: a party glass caddy that sits on a wine bottle: a four-lobed plate of 6 mm ply
# with a 32 mm hole in the middle that slides down the bottle's neck and rests on its
# flare, and four 10 mm slots from the rim (at 45, 135, 225 and 315 deg) in which four wine
# glasses hang upside down by their stems, the stems seated 85 mm from the centre (bottle
# 75 mm across, glass bowls 85 mm across, feet 75 mm across). Lobes: four 90 mm circles
# 70 mm out, on a 140 mm centre disc; every corner rounded R4. "CHEERS" engraved along the
# top of a 45 mm circle round the neck hole, "2027" under it, read the right way up.

units mm
thickness 6 mm

seat_r = 85 mm

solid caddy {
    centre = Circle(center=(0, 0), diameter=140)
    for i in range(4) {
        lobe = Circle(center=(70 * cos(45 deg + i * 90 deg), 70 * sin(45 deg + i * 90 deg)),
                      diameter=90)
    }
    hole neck { c = Circle(center=(0, 0), diameter=32) }
    hole stems {
        for i in range(4) {
            s = Slot(start=(seat_r * cos(45 deg + i * 90 deg), seat_r * sin(45 deg + i * 90 deg)),
                     end=(125 * cos(45 deg + i * 90 deg), 125 * sin(45 deg + i * 90 deg)),
                     width=10)
        }
    }
    drawing words {
        ring = Circle(center=(0, 0), radius=45, construction=true)
        top = Text("CHEERS", along=ring, size=9)
        bottom = Text("2027", along=ring, size=9, flip=true)
    }
    Fillet(4)

    # the request's numbers
    assert neck.c.diameter == 32 mm, "neck hole 32"
    assert len(stems.s) == 4, "four glasses"
    assert stems.s[0].width == 10 mm, "10 mm slots"
    assert distance(stems.s[0].start, neck.c.center) == 85 mm, "stems 85 from the centre"
    assert seat_r - 75 mm / 2 - 85 mm / 2 >= 4 mm, "bowls clear the bottle"
    assert 2 * seat_r * sin(45 deg) - 75 mm >= 5 mm, "feet clear each other"
    assert stems.s[0].width - 8 mm >= 1 mm, "an 8 mm stem slides in"
}
