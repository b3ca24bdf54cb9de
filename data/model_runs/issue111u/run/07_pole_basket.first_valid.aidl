# Camping: a snow basket for a trekking pole, 3 mm polypropylene. Disc 60 mm across; a 11 mm
# hole in the middle for the pole tip; six radial slots 15 mm long x 4 mm wide (round ends)
# centred 20 mm from the middle, the first pointing right (+x), 60 degrees apart; six 4 mm
# holes 24 mm from the middle, halfway (30 degrees) between the slots.

thickness 3 mm

param d = 60 mm, min = 50 mm, max = 100 mm
param tip_d = 11 mm, min = 8 mm, max = 14 mm

solid basket {
    disc = Circle(center=(0, 0), diameter=d)

    hole pole {
        c = Circle(center=(0, 0), diameter=tip_d)
    }

    hole spoke {
        s = Slot(center=(20, 0), length=15, width=4)
    }
    spokes = CircularPattern(spoke, 6, disc.center)

    hole vent {
        v = Circle(center=(0, 0), diameter=4)
    }
    Coincident(vent.v.center, polar(disc.center, 24, 30 deg))
    vents = CircularPattern(vent, 6, disc.center)

    assert disc.diameter == 60 mm, "60 mm disc"
    assert pole.c.diameter == 11 mm, "11 mm pole hole"
    assert len(spokes) == 6 and len(vents) == 6, "six slots, six holes"
    assert spokes[0].s.length == 15 mm and spokes[0].s.width == 4 mm, "slots 15 x 4"
    assert distance(spokes[0].s.center, disc.center) == 20 mm, "slots on 20"
    assert distance(vents[0].v.center, disc.center) == 24 mm, "holes on 24"
}
