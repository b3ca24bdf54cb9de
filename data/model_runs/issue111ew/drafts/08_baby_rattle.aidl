# Request (gifts): a layered wooden rattle for baby Isla, four glued layers of 6 mm birch
# ply (24 mm thick in the hand). Each layer: a round head 70 mm across, a handle 24 mm wide,
# a ball end 36 mm across, head and ball centres 100 mm apart, every inside corner rounded
# R8. The two middle layers have a 46 mm chamber in the head (12 mm deep when glued), holding
# five 14 mm discs cut from the same sheet that rattle inside. The front layer has "ISLA"
# engraved in filled bold letters 14 mm high in the head; the back layer "12.03.2026"
# 7 mm high. In 3D: back (engraving outward), two middles, front, the discs in the chamber.

units mm
thickness 6 mm

def rattle_layer(chamber=false, word="", word_size=14 mm) -> solid {
    head = Circle(center=(0, 100), diameter=70)
    handle = Rectangle(center=(0, 50), width=24, height=100)
    ball = Circle(center=(0, 0), diameter=36)
    if chamber {
        hole room { c = Circle(center=(0, 100), diameter=46) }
    }
    if word != "" {
        drawing name {
            t = Text(word, position=(0, 100), size=word_size, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }
    Fillet(8)
}

assembly rattle {
    back = rattle_layer(word="12.03.2026", word_size=7 mm)
    for i in range(2) {
        middle = rattle_layer(chamber=true)
    }
    front = rattle_layer(word="ISLA")
    for i in range(5) {
        solid disc { d = Circle(center=(0, 0), diameter=14) }
    }

    # on the sheet
    RightOf(middle[0], back, gap=5)
    AlignBottom(middle[0], back)
    RightOf(middle[1], middle[0], gap=5)
    AlignBottom(middle[1], back)
    RightOf(front, middle[1], gap=5)
    AlignBottom(front, back)
    RightOf(disc[0], front, gap=5)
    AlignBottom(disc[0], back)
    for i in range(1, 5) {
        Above(disc[i], disc[i - 1], gap=5)
        AlignLeft(disc[i], disc[0])
    }

    # glued up: the back's engraving outward (down), the discs on it in the chamber
    Place(back, position=(0, 0, 6), face="down")
    Place(middle[0], position=(0, 0, 6), face="up")
    Place(middle[1], position=(0, 0, 12), face="up")
    Place(front, position=(0, 0, 18), face="up")
    Place(disc[0], position=(-15, 100, 6), face="up")
    Place(disc[1], position=(0, 100, 6), face="up")
    Place(disc[2], position=(15, 100, 6), face="up")
    Place(disc[3], position=(-7, 113, 6), face="up")
    Place(disc[4], position=(7, 87, 6), face="up")

    assert front.head.diameter == 70 mm and front.ball.diameter == 36 mm
    assert front.handle.width == 24 mm
    assert distance(front.head.center, front.ball.center) == 100 mm
    assert middle[0].room.c.diameter == 46 mm and middle[1].room.c.diameter == 46 mm
    assert (middle[0].head.diameter - middle[0].room.c.diameter) / 2 >= 10 mm, "chamber wall"
    assert len(disc) == 5 and disc[0].d.diameter == 14 mm
    assert front.name.t.size == 14 mm and back.name.t.size == 7 mm
    assert front.name.bb.width <= 70 mm - 2 * 5 mm, "name within the head, 5 mm margin"
    assert back.name.bb.width <= 60 mm, "date within the head"
}
