# Music: a sound-hole rosette for a cigar-box guitar, 1.5 mm veneer plywood, glued on the top.
# A ring 110 mm across with the 64 mm sound hole in its centre. Twelve 4 mm holes evenly on a
# 78 mm circle (the first at the top). Two engraved border circles, 70 mm and 102 mm across.
# "HANDMADE" engraved 4 mm along the top on an 88 mm circle (baseline), "2026" 4 mm along the
# bottom, read the right way up.

thickness 1.5 mm
param od = 110 mm, min = 100 mm, max = 130 mm
param sound_hole = 64 mm, min = 50 mm, max = 70 mm

solid rosette {
    ring = Circle(center=(0, 0), diameter=od)
    hole sound {
        c = Circle(center=(0, 0), diameter=sound_hole)
    }
    hole dot {
        c = Circle(center=(0, 39), diameter=4)
    }
    dots = CircularPattern(dot, 12, ring.center)
    Coincident(dot.c.center, polar(ring.center, 39, 90 deg))

    drawing deco {
        inner = Circle(center=(0, 0), diameter=70)
        outer = Circle(center=(0, 0), diameter=102)
        path = Circle(center=(0, 0), diameter=88, construction=true)
        top = Text("HANDMADE", along=path, size=4)
        bottom = Text("2026", along=path, size=4, flip=true)
    }
    Concentric(deco.inner, ring)

    assert ring.diameter == 110 mm, "110 across"
    assert sound.c.diameter == 64 mm, "64 mm sound hole"
    assert len(dots) == 12, "twelve dots"
    assert abs(distance(dots[3].c.center, ring.center) - 39 mm) < 0.001, "dots on a 78 mm circle"
    assert dot.c.diameter == 4 mm, "4 mm dots"
    assert deco.inner.diameter == 70 mm and deco.outer.diameter == 102 mm, "border circles"
    assert (od - sound_hole) / 2 == 23 mm, "ring 23 mm wide"
}
