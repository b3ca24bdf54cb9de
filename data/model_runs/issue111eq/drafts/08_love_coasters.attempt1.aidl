# Request: a wedding gift, a set of four drinks coasters that spell L O V E, from 4 mm
# walnut plywood. Each coaster is scalloped: a 88 mm disc with sixteen R6 scallops centred
# on its rim, 100 mm across overall. On each, its letter is engraved filled in 36 mm bold
# serif capitals in the middle, inside an engraved ring 64 mm across; the couple's names
# "ANNA & JOE" are engraved along the bottom (3.5 mm letters, reading the right way up,
# hanging inside a 73 mm circle) and 24 filled dots 2.4 mm across on a 79 mm circle run
# all round near the edge. Four parts.

units mm
thickness 4 mm
kerf 0.1 mm

word = ["L", "O", "V", "E"]

def coaster(letter="L") -> solid {
    disc = Circle(center=(0, 0), diameter=88)
    scallop = Circle(center=(44, 0), radius=6)
    scallops = CircularPattern(scallop, 16, (0, 0))
    drawing art {
        ring = Circle(center=(0, 0), diameter=64)
        big = Text(letter, position=(0, 0), size=36, font="serif:Bold", valign="middle", fill=true)
        names_path = Circle(center=(0, 0), diameter=73, construction=true)
        names = Text("ANNA & JOE", along=names_path, flip=true, size=3.5, font="sans")
        dot = Circle(center=(39.5, 0), diameter=2.4, fill=true)
        dots = CircularPattern(dot, 24, (0, 0))
    }
    Fixed(disc)
}

assembly love {
    for i in range(4) {
        coasters = coaster(letter=word[i])
    }
    RightOf(coasters[1], coasters[0], gap=5)
    AlignBottom(coasters[1], coasters[0])
    RightOf(coasters[2], coasters[1], gap=5)
    AlignBottom(coasters[2], coasters[1])
    RightOf(coasters[3], coasters[2], gap=5)
    AlignBottom(coasters[3], coasters[2])

    assert len(coasters) == 4, "four coasters"
    assert coasters[0].disc.diameter == 88 mm, "88 mm disc"
    assert len(coasters[0].scallops) == 16 and coasters[0].scallop.radius == 6 mm, "sixteen R6 scallops"
    assert coasters[0].bb.width == 100 mm and coasters[0].bb.height == 100 mm, "100 mm across"
    assert coasters[0].art.ring.diameter == 64 mm, "ring 64 mm"
    assert coasters[1].art.big.size == 36 mm, "36 mm letters"
    assert coasters[1].art.big.bb.width <= 64 mm - 16 mm and coasters[1].art.big.bb.height <= 64 mm - 16 mm,
        "the letter well inside the ring"
    assert len(coasters[0].art.dots) == 24 and coasters[0].art.dot.diameter == 2.4 mm, "24 dots of 2.4 mm"
    assert distance(coasters[0].art.dot.center, coasters[0].disc.center) == 79 mm / 2, "dots on a 79 mm circle"
    assert distance(coasters[0].art.names, coasters[0].art.dots) >= 1 mm, "names clear of the dots"
    assert distance(coasters[0].art.names, coasters[0].art.ring) >= 1 mm, "names clear of the ring"
}
