# Sheriff's star badge: a six-pointed star 80 mm across the tips (outer radius 40 mm,
# inner radius 23 mm) whose tips are rounded with a 4 mm radius; a 2 mm pin hole
# pair for the clasp 10 mm apart, 12 mm above the centre... no: the clasp is glued,
# so no holes. Engraved: a 30 mm circle in the middle with "SHERIFF" (5 mm) across it,
# and a small five-pointed star emblem (made at 12 mm radius, then scaled to 70 %)
# above the word.
param r = 40 mm, min = 25 mm, max = 60 mm

solid badge {
    star = Star(center=(0, 0), points=6, outer_radius=r, inner_radius=0.575 * r,
                tip_radius=4)

    drawing engraving {
        ring = Circle(center=(0, 0), diameter=30)
        word = Text("SHERIFF", position=(0, -4), size=5, valign="middle")
        emblem = Star(center=(0, 7), points=5, outer_radius=6, inner_radius=2.5)
    }
    Scale(engraving.emblem, 0.7)
    CenterInside(engraving.ring, star)
    At(engraving.word.position, engraving.ring.center, dy=-4)
    At(engraving.emblem.center, engraving.ring.center, dy=6)
}
