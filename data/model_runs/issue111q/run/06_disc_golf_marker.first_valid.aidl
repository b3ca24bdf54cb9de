# Sport: a disc-golf mini marker disc, 80 mm across, 3 mm acrylic. "ACE" in bold sans, 16 mm
# capitals, cut through as a stencil (counters held), centred. A ring of twelve 4 mm holes on a
# 64 mm circle (radius 32). A five-point star (outer radius 8, inner 3.5) engraved 20 mm above
# the centre and "MINI" 5 mm engraved 20 mm below it.

thickness 3 mm

solid marker {
    disc = Circle(center=(0, 0), diameter=80)

    hole word {
        t = Text("ACE", (0, 0), size=16, font="sans:Bold", stencil=true, valign="middle")
    }
    CenterInside(word, disc)

    hole dot {
        c = Circle(center=(0, 32), diameter=4)
    }
    dots = CircularPattern(dot, 12, disc.center)
    At(dot.c.center, disc.center, dy=32)

    drawing deco {
        star = Star(center=(0, 20), points=5, outer_radius=8, inner_radius=3.5)
        mini = Text("MINI", (0, -20), size=5, valign="middle")
    }
    At(deco.star.center, disc.center, dy=20)
    At(deco.mini.position, disc.center, dy=-20)

    assert disc.diameter == 80 mm, "80 mm disc"
    assert len(dots) == 12, "twelve holes"
    assert distance(dots[3].c.center, disc.center) == 32 mm, "on radius 32"
    assert dot.c.diameter == 4 mm, "4 mm holes"
}
