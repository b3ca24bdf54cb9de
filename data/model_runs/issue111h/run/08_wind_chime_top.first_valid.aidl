# Garden wind-chime top: a 120 mm disc of 4 mm ply. Six 4 mm holes for the chime tubes'
# cords evenly on a 48 mm radius, the first at +x. A 4 mm centre hole for the clapper cord.
# Three 3 mm hanging holes on a 20 mm radius at 90, 210 and 330 deg. Three decorative arc
# slots 6 mm wide on a 32 mm radius, each spanning 80 deg, centred at 30, 150 and 270 deg
# (between the hanging holes). "LISTEN TO THE WIND" engraved 4 mm high along a 53 mm
# radius over the top.

units mm
thickness 4 mm

import "std/plates.aidl"

param tubes = 6, min = 3, max = 8
param tube_r = 48 mm, min = 40 mm, max = 52 mm

solid chime_top {
    disc = Circle(center=(0, 0), diameter=120)

    hole chime { c = Circle(center=(48, 0), diameter=4) }
    chimes = CircularPattern(chime, tubes, disc.center)
    Coincident(chime.c.center, polar(disc.center, tube_r, 0 deg))

    hole clapper { c = Circle(center=(0, 0), diameter=4) }
    Concentric(clapper.c, disc)

    hole hanger { c = Circle(center=(0, 20), diameter=3) }
    hangers = CircularPattern(hanger, 3, disc.center)
    Coincident(hanger.c.center, polar(disc.center, 20, 90 deg))

    hole deco { a = ArcSlot(center=(0, 0), radius=32, start_angle=-10 deg, end_angle=70 deg, width=6) }
    decos = CircularPattern(deco, 3, disc.center)
    Concentric(deco.a, disc)

    words = text_on_arc(text="LISTEN TO THE WIND", radius=53 mm, size=4 mm, angle=90 deg)

    assert disc.diameter == 120 mm, "120 mm disc"
    assert len(chimes) == 6, "six chime holes"
    assert chime.c.diameter == 4 mm, "4 mm chime holes"
    assert distance(chime.c.center, disc.center) == 48 mm, "chime holes on r 48"
    assert distance(chimes[3].c.center, disc.center) == 48 mm, "every chime hole on r 48"
    assert chime.c.center.y == disc.center.y and chime.c.center.x > disc.center.x, "first at +x"
    assert clapper.c.diameter == 4 mm, "4 mm clapper hole"
    assert distance(clapper.c.center, disc.center) == 0 mm, "clapper hole centred"
    assert len(hangers) == 3, "three hanging holes"
    assert hanger.c.diameter == 3 mm, "3 mm hanging holes"
    assert distance(hangers[1].c.center, disc.center) == 20 mm, "hanging holes on r 20"
    assert hanger.c.center.x == disc.center.x and hanger.c.center.y > disc.center.y, "first hanger at 90 deg"
    assert len(decos) == 3, "three arc slots"
    assert deco.a.radius == 32 mm and deco.a.width == 6 mm, "arc slots r 32, 6 wide"
    assert words.ch[0].size == 4 mm, "4 mm letters"
    assert min([distance(c.position, disc.center) for c in words.ch]) > 50 mm, "text clear of the chime holes"
}
