# Request (camping, nature): a pocket animal-track card for hikers, 3 mm birch ply.
# - Card 160 x 90 mm with 6 mm corner radii, a 5 mm lanyard hole centred 8 mm in from the
#   top and left edges.
# - Three footprints engraved filled at life size, their centres 46 mm apart along a line
#   12 mm above the card's centre: a red fox (a heel pad of three merged round lobes, two
#   front toes 10 x 15 mm, two side toes 10 x 14 mm leaning out 20 deg), a roe deer (two
#   halves of a cloven hoof, each a point over a 14 mm round heel, 2 mm apart at the heel)
#   and a badger (a wide heel pad, five toes 7 x 11 mm on an arc of 24 mm radius at 50 to
#   130 deg, each with a 4 mm claw line beyond it).
# - Each animal's name under its print, 4 mm letters, baseline 20 mm under the card's centre.
# - A millimetre scale along the bottom edge: 0 at 10 mm from the left edge, to 140 mm; ticks
#   start 1 mm above the edge, 2 mm long, every 5 mm 3.5 mm, every 10 mm 5 mm with the cm
#   number (0 to 14) in 2.5 mm figures 1 mm above it.
# - Everything engraved at least 3 mm in from the edges.

units mm
thickness 3 mm

fox_x = -46 mm
deer_x = 0 mm
badger_x = 46 mm
row_y = 12 mm

solid card {
    body = RoundedRectangle(center=(0, 0), width=160, height=90, corner_radius=6)
    hole lanyard { c = Circle(center=(-72, 37), diameter=5) }

    drawing fox {
        heel = Hull(Circle(center=(fox_x - 9, row_y - 18), radius=5), Circle(center=(fox_x + 9, row_y - 18), radius=5),
                    Circle(center=(fox_x, row_y - 9), radius=6), fill=true)
        front_left = Ellipse(center=(fox_x - 6, row_y + 18), rx=5, ry=7.5, fill=true)
        front_right = Ellipse(center=(fox_x + 6, row_y + 18), rx=5, ry=7.5, fill=true)
        side_left = Ellipse(center=(fox_x - 16, row_y + 1), rx=5, ry=7, rotation=20 deg, fill=true)
        side_right = Ellipse(center=(fox_x + 16, row_y + 1), rx=5, ry=7, rotation=-20 deg, fill=true)
    }
    drawing deer {
        left_half = Hull(Point(deer_x - 2.5, row_y + 20), Circle(center=(deer_x - 8, row_y - 12), radius=7), fill=true)
        right_half = Hull(Point(deer_x + 2.5, row_y + 20), Circle(center=(deer_x + 8, row_y - 12), radius=7), fill=true)
    }
    drawing badger {
        heel = Hull(Circle(center=(badger_x - 14, row_y - 12), radius=7), Circle(center=(badger_x + 14, row_y - 12), radius=7),
                    Circle(center=(badger_x, row_y - 6), radius=9), fill=true)
        for a in range(50, 131, 20) {
            toe = Ellipse(center=polar((badger_x, row_y - 8), 24, a * 1 deg), rx=3.5, ry=5.5, rotation=(a - 90) * 1 deg, fill=true)
            claw = Line(polar((badger_x, row_y - 8), 31, a * 1 deg), polar((badger_x, row_y - 8), 35, a * 1 deg))
        }
    }
    drawing names {
        fox_name = Text("RED FOX", position=(fox_x, -20), size=4)
        deer_name = Text("ROE DEER", position=(deer_x, -20), size=4)
        badger_name = Text("BADGER", position=(badger_x, -20), size=4)
    }
    drawing scale {
        for i in range(0, 141) {
            tick = Line((-70 + i, -44), (-70 + i, -44 + (5 if i % 10 == 0 else (3.5 if i % 5 == 0 else 2))))
        }
        for c in range(0, 15) {
            num = Text(str(c), position=(-70 + 10 * c, -38), size=2.5)
        }
    }

    # the request's numbers
    assert body.width == 160 mm and body.height == 90 mm, "card 160 x 90"
    assert lanyard.c.diameter == 5 mm, "lanyard hole 5"
    assert lanyard.c.center.x - body.bb.left == 8 mm and body.bb.top - lanyard.c.center.y == 8 mm, "8 in from top and left"
    assert deer_x - fox_x == 46 mm and badger_x - deer_x == 46 mm, "prints 46 apart"
    assert row_y - body.center.y == 12 mm, "prints 12 above the centre"
    assert len(badger.toe) == 5 and len(badger.claw) == 5, "five badger toes with claws"
    assert badger.claw[0].length == 4 mm, "4 mm claws"
    assert abs(distance(deer.left_half, deer.right_half) - 2 mm) < 0.01 mm, "hoof halves 2 apart"
    assert len(scale.tick) == 141 and len(scale.num) == 15, "0 to 140 mm, 0 to 14 cm"
    assert scale.tick[0].start.x - body.bb.left == 10 mm, "0 at 10 from the left edge"
    assert scale.tick[0].start.y - body.bb.bottom == 1 mm, "ticks 1 above the edge"
    assert scale.tick[10].length == 5 mm and scale.tick[5].length == 3.5 mm and scale.tick[1].length == 2 mm, "tick lengths"
    assert scale.num[0].position.y - scale.tick[0].end.y == 1 mm, "numbers 1 above the cm ticks"
    assert names.fox_name.position.y - body.center.y == -20 mm, "names 20 under the centre"
    assert distance(fox, lanyard) >= 3 mm, "fox clear of the lanyard hole"
    assert distance(names, fox) >= 2 mm and distance(names, deer) >= 2 mm and distance(names, badger) >= 2 mm, "names clear of the prints"
    assert distance(fox, deer) >= 3 mm and distance(deer, badger) >= 3 mm, "prints apart"
    assert badger.bb.top <= body.bb.top - 3 mm and fox.bb.left >= body.bb.left + 3 mm and badger.bb.right <= body.bb.right - 3 mm, "3 mm in from the edges"
}
