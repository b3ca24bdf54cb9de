# Request: a pool-party drink float shaped like an iced donut, laser-cut from 10 mm EVA
# foam in three glued layers. Base: a 200 mm disc with a 60 mm drain hole in the middle
# (the cup sits on its ledge). Body: a 200 mm ring with an 88 mm cup hole. Icing (pink
# foam) on top: a wavy ring, 10 drips round, its outer edge swinging between 79 and 91 mm
# from the centre, the same 88 mm cup hole, and 14 sprinkles (10 x 3 mm slots, rounded)
# cut through it so the tan body shows, alternately 55 and 70 mm from the centre, each
# turned a different way. Shown stacked for the party photo.

units mm
thickness 10 mm

param d_out = 200 mm, min = 160, max = 260
param cup = 88 mm, min = 70, max = 100
waves = 10
n_spr = 14

assembly donut_float {
    solid base {
        disc = Circle(center=(0, 0), diameter=d_out)
        hole drain { c = Circle(center=(0, 0), diameter=60) }
    }
    solid body {
        ring = Circle(center=(0, 0), diameter=d_out)
        hole well { c = Circle(center=(0, 0), diameter=cup) }
    }
    solid icing {
        edge = Spline([polar((0, 0), 85 mm + 6 mm * cos(waves * i * 9 deg), i * 9 deg)
                       for i in range(40)], closed=true)
        hole well { c = Circle(center=(0, 0), diameter=cup) }
        hole sprinkles {
            for k in range(n_spr) {
                s = Slot(center=polar((0, 0), 55 mm if k % 2 == 0 else 70 mm,
                                      k * 360 deg / n_spr + 7 deg),
                         length=10, width=3, rotation=k * 67 deg)
            }
        }
    }
    RightOf(body, base, gap=15)
    AlignCenterY(body, base)
    RightOf(icing, body, gap=15)
    AlignCenterY(icing, body)

    Place(base, position=(0, 0, 0))
    Place(body, position=(0, 0, 10))
    Place(icing, position=(0, 0, 20))

    assert base.disc.diameter == 200 mm and base.drain.c.diameter == 60 mm, "base"
    assert body.well.c.diameter == 88 mm and icing.well.c.diameter == 88 mm, "cup hole 88"
    assert len(icing.sprinkles.s) == 14, "14 sprinkles"
    assert distance(icing.sprinkles.s[1].center, icing.well.c.center) == 70 mm, "70 out"
    assert distance(icing.sprinkles.s[0].center, icing.well.c.center) == 55 mm, "55 out"
    assert distance(icing.edge.points[0], icing.well.c.center) == 91 mm, "drip out to 91"
    assert distance(icing.edge.points[2], icing.well.c.center) == 79 mm, "drip in to 79"
}
