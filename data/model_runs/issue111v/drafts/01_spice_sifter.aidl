# Kitchen: sifter insert for a spice jar. A 3 mm disc 68 mm across that sits in the
# jar's lid; sprinkle holes of 3 mm: one in the centre, 6 on a 16 mm circle, 12 on a
# 32 mm circle; a pour opening: a 36 mm long x 8 mm wide slot whose centre is 24 mm
# above the disc's centre (a straight slot along x); a lift tab 14 mm wide sticking out
# 6 mm at the bottom with a 4 mm hole; "PAPRIKA" engraved 4 mm high 25 mm below centre.
thickness 3 mm

param d = 68 mm, min = 50 mm, max = 90 mm

solid sifter {
    disc = Circle(center=(0, 0), diameter=d)
    tab = RoundedRectangle(center=(0, -d / 2 - 1), width=14, height=14, corner_radius=4)
    Fixed(disc)
    # the tab sticks out 6 mm below the rim
    tab.bb.bottom == disc.bb.bottom - 6 mm
    AlignCenterX(tab, disc)

    hole mid { c = Circle(center=(0, 0), diameter=3) }
    hole inner { c = Circle(center=(8, 0), diameter=3) }
    hole outer { c = Circle(center=(16, 0), diameter=3) }
    ring1 = CircularPattern(inner, 6, disc.center)
    ring2 = CircularPattern(outer, 12, disc.center)
    Concentric(mid.c, disc)
    Coincident(inner.c.center, polar(disc.center, 8, 0 deg))
    Coincident(outer.c.center, polar(disc.center, 16, 0 deg))

    hole pour { s = Slot(center=(0, 24), length=36, width=8) }
    AlignCenterX(pour, disc)
    pour.s.center.y == disc.center.y + 24 mm

    hole lift { c = Circle(center=(0, -d / 2 - 2), diameter=4) }
    AlignCenterX(lift, tab)
    lift.c.center.y == disc.bb.bottom - 2 mm

    drawing label { t = Text("PAPRIKA", (0, -25), size=4, valign="middle") }
    AlignCenterX(label, disc)
    label.t.position.y == disc.center.y - 25 mm

    assert disc.diameter == 68 mm, "disc 68 across"
    assert len(ring1) == 6 and len(ring2) == 12, "6 and 12 holes"
    assert disc.bb.bottom - tab.bb.bottom == 6 mm, "tab sticks out 6"
    assert pour.s.length == 36 mm and pour.s.width == 8 mm, "pour slot 36 x 8"
    assert distance(outer.c.center, disc.center) == 16 mm, "outer ring on 32 mm circle"
}
