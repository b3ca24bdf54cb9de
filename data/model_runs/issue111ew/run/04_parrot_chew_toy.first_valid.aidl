# Request (pets): a hanging chew and foraging toy for Kiwi the cockatiel, cut from 4 mm
# unfinished birch ply (bird-safe), every piece threaded on a 6 mm sisal rope through an
# 8 mm centre hole. Top to bottom, 30 mm apart on the rope (knots between):
# - a treat disc 80 mm across with eight 10 mm treat holes on a 60 mm circle, "KIWI"
#   engraved 7 mm high above the rope hole;
# - a hexagon bead 30 mm across the flats with an engraved 20 mm ring;
# - a six-petal flower, 70 mm tip to tip with the tips rounded R4, six 5 mm holes 24 mm
#   out on the petals for threading paper strips;
# - a second hexagon bead like the first;
# - an eight-point star 40 mm tip to tip (inner radius 12) as the bottom stop.

units mm
thickness 4 mm

def hex_bead(af=30 mm) -> solid {
    body = RegularPolygon(center=(0, 0), across_flats=af, sides=6)
    hole rope { c = Circle(center=(0, 0), diameter=8) }
    drawing ring { c = Circle(center=(0, 0), diameter=20) }
}

assembly parrot_toy {
    solid disc {
        body = Circle(center=(0, 0), diameter=80)
        hole rope { c = Circle(center=(0, 0), diameter=8) }
        hole treat { c = Circle(center=(0, 30), diameter=10) }
        treats = CircularPattern(treat, 8, (0, 0))
        drawing name {
            t = Text("KIWI", position=(0, 12), size=7, valign="middle")
        }
    }

    for i in range(2) {
        bead = hex_bead()
    }

    solid flower {
        petals = Star(center=(0, 0), points=6, outer_radius=35, inner_radius=22, tip_radius=4)
        hole rope { c = Circle(center=(0, 0), diameter=8) }
        hole strip { c = Circle(center=(0, 24), diameter=5) }
        strips = CircularPattern(strip, 6, (0, 0))
    }

    solid stop {
        s = Star(center=(0, 0), points=8, outer_radius=20, inner_radius=12)
        hole rope { c = Circle(center=(0, 0), diameter=8) }
    }

    # on the sheet: a row
    RightOf(bead[0], disc, gap=5)
    RightOf(flower, bead[0], gap=5)
    RightOf(bead[1], flower, gap=5)
    RightOf(stop, bead[1], gap=5)
    AlignCenterY(bead[0], disc)
    AlignCenterY(flower, disc)
    AlignCenterY(bead[1], disc)
    AlignCenterY(stop, disc)

    # on the rope, lying flat, 30 mm apart
    Place(disc, position=(0, 0, 200), face="up")
    Place(bead[0], position=(0, 0, 170), face="up")
    Place(flower, position=(0, 0, 140), face="up")
    Place(bead[1], position=(0, 0, 110), face="up")
    Place(stop, position=(0, 0, 80), face="up")

    assert disc.body.diameter == 80 mm
    assert len(disc.treats) == 8 and disc.treat.c.diameter == 10 mm
    assert distance(disc.body.center, disc.treats[3].c.center) == 30 mm, "60 mm circle"
    assert distance(disc.name, disc.treats) >= 2 mm and distance(disc.name, disc.rope) >= 2 mm
    assert len(bead) == 2 and bead[0].body.across_flats == 30 mm
    assert flower.petals.outer_radius * 2 == 70 mm and flower.petals.tip_radius == 4 mm
    assert len(flower.strips) == 6 and flower.strip.c.diameter == 5 mm
    assert distance(flower.petals.center, flower.strips[2].c.center) == 24 mm
    assert stop.s.outer_radius * 2 == 40 mm and stop.s.inner_radius == 12 mm
    assert disc.rope.c.diameter == 8 mm and flower.rope.c.diameter == 8 mm and
        stop.rope.c.diameter == 8 mm and bead[1].rope.c.diameter == 8 mm
}
