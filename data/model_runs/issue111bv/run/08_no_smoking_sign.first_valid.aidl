# Request: a layered "NO SMOKING" wall sign from 3 mm acrylic, 220 x 320 mm (4 parts). A white
# base (corners rounded 10 mm) with four 4.5 mm screw holes 12 mm in from the corners,
# countersunk 9 mm. On it, all inlaid at the same level (3 mm), a red ring 190 mm across and
# 18 mm wide, its centre 105 mm below the base's top, with an 18 mm slash at -45 deg across
# it (one red piece); a black cigarette 130 x 18 mm lying across the ring 5 mm below its
# centre, cut where the slash crosses it with 0.3 mm play each side, with an engraved filter
# line 30 mm from its left end and two 3 mm smoke wisps rising 40 mm from its right end
# (black, one piece with it); and "NO SMOKING" in black bold letters 22 mm tall, no wider
# than 180 mm, standing on a 4 mm rail as wide as the word, its baseline 50 mm above the
# base's bottom.

thickness 3 mm

BW = 220 mm
BH = 320 mm
RING_D = 190 mm
RING_W = 18 mm
CY = BH / 2 - 105 mm        # ring centre, base centred at (0, 0)
SLASH_W = 18 mm
PLAY = 0.3 mm
CIG_L = 130 mm
CIG_H = 18 mm
CIG_Y = CY - 5 mm
BASELINE = -BH / 2 + 50 mm

assembly no_smoking {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=BW, height=BH, corner_radius=10 mm)
        hole screw { c = Circle(center=(-BW / 2 + 12 mm, -BH / 2 + 12 mm), diameter=4.5 mm) }
        screws = CornerPattern(screw, plate, inset=12 mm)
        Countersink(screw, diameter=9 mm)
    }

    solid red {
        ring = Circle(center=(0, CY), diameter=RING_D)
        hole inner { c = Circle(center=(0, CY), diameter=RING_D - 2 * RING_W) }
        solid slash {
            bar = Rectangle(center=(0, CY), width=RING_D - RING_W, height=SLASH_W,
                            rotation=-45 deg)
        }
    }

    solid black {
        cig = Rectangle(center=(0, CIG_Y), width=CIG_L, height=CIG_H)
        smoke1 = Stroke(Spline([(CIG_L / 2 - 18, CIG_Y + CIG_H / 2 - 1), (CIG_L / 2 - 23, CIG_Y + 22),
                                (CIG_L / 2 - 15, CIG_Y + 34), (CIG_L / 2 - 20, CIG_Y + CIG_H / 2 + 40)]),
                        width=3 mm)
        smoke2 = Stroke(Spline([(CIG_L / 2 - 6, CIG_Y + CIG_H / 2 - 1), (CIG_L / 2 - 11, CIG_Y + 20),
                                (CIG_L / 2 - 3, CIG_Y + 30), (CIG_L / 2 - 8, CIG_Y + CIG_H / 2 + 36)]),
                        width=3 mm)
        hole gap {
            g = Rectangle(center=(0, CY), width=RING_D, height=SLASH_W + 2 * PLAY, rotation=-45 deg)
        }
        drawing filter {
            l = Line((-CIG_L / 2 + 30 mm, CIG_Y - CIG_H / 2 + 1 mm), (-CIG_L / 2 + 30 mm, CIG_Y + CIG_H / 2 - 1 mm))
        }
    }

    solid word {
        t = Text("NO SMOKING", position=(0, BASELINE), size=22, font="sans:Bold", max_width=180 mm)
        rail = Rectangle(center=(0, BASELINE - 1 mm), width=t.bb.width, height=4 mm)
    }

    # flat: the pieces beside the base for cutting
    RightOf(red, base, gap=8)
    AlignTop(red, base)
    Below(black, red, gap=8)
    AlignLeft(black, red)
    Below(word, black, gap=8)
    AlignLeft(word, red)

    # assembled: the coloured pieces inlaid on the base
    Place(base, position=(0, 0, 0))
    Place(red, position=(0, 0, 3 mm))
    Place(black, position=(0, 0, 3 mm))
    Place(word, position=(0, 0, 3 mm))

    assert base.plate.bb.width == 220 mm and base.plate.bb.height == 320 mm, "220 x 320"
    assert red.ring.diameter == 190 mm, "190 mm ring"
    assert red.ring.radius - red.inner.c.radius == 18 mm, "18 mm wide ring"
    assert BH / 2 - CY == 105 mm, "ring centre 105 mm below the top"
    assert red.ring.bb.top - red.inner.c.bb.top == 18 mm, "ring"
    assert black.cig.bb.width == 130 mm, "130 mm cigarette"
    assert word.t.bb.width <= 180 mm, "word no wider than 180 mm"
    assert BASELINE + BH / 2 == 50 mm, "baseline 50 mm up"
    # the cigarette and smoke stay inside the ring's opening
    assert CIG_L / 2 < sqrt((RING_D / 2 - RING_W) ** 2 - (CIG_Y - CY + CIG_H / 2) ** 2),
        "cigarette inside the ring"
}
