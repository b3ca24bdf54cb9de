# Bathroom shower-drain hair catcher: an 80 mm disc of 2 mm acrylic laid over the drain. Drain holes
# 3 mm across: one in the centre, 6 evenly round a 10 mm radius, 12 round 20 mm and 18 round 30 mm
# (37 in all). A pull tab at the top: a round-ended lug 16 mm wide that reaches 10 mm past the rim,
# with a 5 mm hole for a string concentric with its round end; the tab's joins to the disc R2.

units mm
thickness 2 mm

param dia = 80 mm, min = 60, max = 120
param hole_d = 3 mm, min = 2, max = 4

def drain(d=3 mm) -> hole {
    c = Circle(center=(0, 0), diameter=d)
}

solid catcher {
    disc = Circle(center=(0, 0), diameter=dia)
    tab = Slot(start=(0, dia / 2 - 6), end=(0, dia / 2 + 2), width=16)

    hole string {
        c = Circle(center=(0, dia / 2 + 2), diameter=5)
    }
    Concentric(string.c, tab.end)

    middle = drain(d=hole_d)
    Concentric(middle.c, disc)

    r10 = drain(d=hole_d)
    ring10 = CircularPattern(r10, 6, disc.center)
    Coincident(r10.c.center, polar(disc.center, 10, 0 deg))

    r20 = drain(d=hole_d)
    ring20 = CircularPattern(r20, 12, disc.center)
    Coincident(r20.c.center, polar(disc.center, 20, 0 deg))

    r30 = drain(d=hole_d)
    ring30 = CircularPattern(r30, 18, disc.center)
    Coincident(r30.c.center, polar(disc.center, 30, 0 deg))

    # the only corners of the outline are where the tab meets the disc
    Fillet(2)

    assert disc.diameter == 80 mm, "80 mm disc"
    assert len(ring10) == 6 and len(ring20) == 12 and len(ring30) == 18, "6, 12 and 18 holes"
    assert 1 + len(ring10) + len(ring20) + len(ring30) == 37, "37 holes in all"
    assert r30.c.diameter == 3 mm, "3 mm holes"
    assert distance(r20.c.center, disc.center) == 20 mm, "second ring at R20"
    assert tab.bb.top - disc.bb.top == 10 mm, "tab 10 past the rim"
    assert tab.width == 16 mm, "tab 16 wide"
    assert string.c.diameter == 5 mm, "string hole 5"
}
