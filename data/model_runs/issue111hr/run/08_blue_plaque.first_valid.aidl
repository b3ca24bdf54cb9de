# Request (signs): a round "blue plaque" for a local history society to mark a house, two
# layers of 3 mm acrylic. A blue base disc 300 mm across with the words engraved filled
# (they come out frosted white): "WESTBURY HISTORY SOCIETY" (10 mm bold) along the top on a
# 105 mm radius, then centred lines "HENRY ALDER" (24 mm bold, at most 200 mm wide) with its
# middle 35 mm above the centre, "1862 - 1931" (16 mm bold) on the centre, "Clockmaker" (14 mm)
# 32 mm below the centre and "lived and worked here" (12 mm) 60 mm below it. A white rim ring
# 300 mm outside, 270 mm inside, is glued on top. Four 4.5 mm screw holes through both layers
# on a 142.5 mm radius at 45, 135, 225 and 315 deg, countersunk 9 mm in the ring. Every word
# at least 5 mm inside the ring and 5 mm from the screws.

units mm
thickness 3 mm

assembly plaque {
    solid base {
        disc = Circle(center=(0, 0), diameter=300)
        hole screw { c = Circle(center=(142.5 * cos(45 deg), 142.5 * sin(45 deg)), diameter=4.5) }
        screws = CircularPattern(screw, 4, (0, 0))
        drawing words {
            arc = Circle(center=(0, 0), radius=105, construction=true)
            society = Text("WESTBURY HISTORY SOCIETY", along=arc, size=10, font="sans:Bold", fill=true)
            name = Text("HENRY ALDER", position=(0, 35), size=24, font="sans:Bold", valign="middle",
                        max_width=200, fill=true)
            years = Text("1862 - 1931", position=(0, 0), size=16, font="sans:Bold", valign="middle", fill=true)
            trade = Text("Clockmaker", position=(0, -32), size=14, font="sans", valign="middle", fill=true)
            lived = Text("lived and worked here", position=(0, -60), size=12, font="sans", valign="middle",
                         fill=true)
        }
    }
    Place(base, position=(0, 0, 0))

    solid ring {
        outer = Circle(center=(0, 0), diameter=300)
        hole inner { c = Circle(center=(0, 0), diameter=270) }
        hole screw { c = Circle(center=(142.5 * cos(45 deg), 142.5 * sin(45 deg)), diameter=4.5) }
        screws = CircularPattern(screw, 4, (0, 0))
        Countersink(screw, diameter=9 mm)
    }
    RightOf(ring, base, gap=10)
    AlignTop(ring, base)
    Place(ring, position=(0, 0, 3))

    # the request's numbers
    assert base.disc.diameter == 300 mm and ring.outer.diameter == 300 mm and ring.inner.c.diameter == 270 mm,
        "disc 300, ring 300 / 270"
    assert len(base.screws) == 4 and len(ring.screws) == 4, "four screws"
    assert norm(ring.screws[0].c.center - ring.outer.center) == 142.5 mm, "screws on a 142.5 radius"
    assert norm(base.screws[2].c.center - base.disc.center) == 142.5 mm, "base screws on a 142.5 radius"
    assert base.words.name.position.y - base.disc.center.y == 35 mm, "name 35 above the centre"
    assert base.disc.center.y - base.words.trade.position.y == 32 mm, "trade 32 below"
    assert base.disc.center.y - base.words.lived.position.y == 60 mm, "lived here 60 below"
    assert base.words.name.bb.width <= 200 mm, "name at most 200 wide"
    # every word 5 mm inside the ring's 135 mm radius: the corners of each line's box
    assert norm(base.words.name.bb.top_right - base.disc.center) <= 130 mm, "name inside the ring"
    assert norm(base.words.lived.bb.bottom_right - base.disc.center) <= 130 mm, "bottom line inside the ring"
    assert base.words.society.bb.top - base.disc.center.y <= 130 mm, "society inside the ring"
    assert distance(base.words, base.screws) >= 5 mm, "words clear of the screws"
    assert distance(base.words.society, base.words.name) >= 5 mm, "arc text clear of the name"
}
