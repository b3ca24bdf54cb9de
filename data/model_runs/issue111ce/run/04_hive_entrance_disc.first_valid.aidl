# Request (garden): a beehive entrance disc, 3 mm outdoor ply. A 100 mm disc turns on one M4
# screw through its centre, over the hive's 25 mm entrance hole; four openings sit 28 mm from
# the centre, 90 deg apart, one over the hive hole at a time: OPEN (a 25 mm hole, at 0 deg),
# BEE (one 9 mm hole, at 90 deg), QUEEN (an excluder: three slots 4.2 mm wide, 20 mm long,
# 7 mm apart, running radially, at 180 deg) and VENT (nine 3 mm holes on a 5 mm grid, at
# 270 deg). Each opening's name is engraved 4 mm high on a circle of 44 mm radius at the
# opening's angle. Thirty r2.5 grip scallops round the rim.

import "std/fasteners.aidl"

thickness 3 mm

R = 50 mm       # the disc's radius
r_open = 28 mm  # the openings' centres from the disc's centre

solid entrance_disc {
    disc = Circle(center=(0, 0), diameter=100)
    pivot = clearance_hole(size=4)
    Concentric(pivot.c, disc)

    hole open { c = Circle(center=(r_open, 0), diameter=25) }
    hole bee { c = Circle(center=(0, r_open), diameter=9) }
    hole queen {
        for k in range(3) {
            s = Slot(center=(-r_open, (k - 1) * 7 mm), length=20, width=4.2)
        }
    }
    hole vent { v = Circle(center=(-5, -r_open - 5 mm), diameter=3) }
    vents = GridPattern(vent, 3, 3, (5, 5))

    Coincident(open.c.center, polar(disc.center, r_open, 0 deg))
    Coincident(bee.c.center, polar(disc.center, r_open, 90 deg))
    At(queen.bb.center, polar(disc.center, r_open, 180 deg))

    hole grip { n = Circle(center=(R, 0), radius=2.5) }
    scallops = CircularPattern(grip, 30, disc.center)

    drawing labels {
        ring = Circle(center=(0, 0), radius=44, construction=true)
        names = ["OPEN", "BEE", "QUEEN", "VENT"]
        for k in range(4) {
            t = Text(names[k], along=ring, angle=k * 90 deg, size=4, valign="middle")
        }
    }
    Concentric(labels.ring, disc)

    assert disc.diameter == 100 mm, "100 mm disc"
    assert open.c.diameter == 25 mm, "25 mm open hole"
    assert bee.c.diameter == 9 mm, "9 mm bee hole"
    assert len(queen.s) == 3 and queen.s[0].width == 4.2 mm and queen.s[0].length == 20 mm,
        "three 4.2 x 20 excluder slots"
    assert queen.s[1].center.y - queen.s[0].center.y == 7 mm, "slots 7 apart"
    assert len(vents) == 9, "nine vent holes"
    assert distance(open.c.center, disc.center) == 28 mm, "openings 28 from the centre"
    assert distance(vents[4].v.center, disc.center) == 28 mm, "vent grid centred 28 out"
    assert len(scallops) == 30, "thirty grip scallops"
}
