# Request: a personalised hair barrette as a gift, in 3 mm birch ply, with its presentation
# card. The barrette is an oval 80 x 26 with a scalloped edge (20 bumps of 3 mm radius set
# round the oval), initials "EM" engraved filled in serif bold 8 mm in the middle, four little
# five-pointed stars cut through (4 mm tip radius, 1.8 mm notches) at 14 and 24 mm either
# side of the middle, and two 2 mm rivet holes for the metal clip 66 mm apart on the centre
# line. The card is 110 x 70 with 5 mm round corners, "FOR EMMA" engraved along the top
# (5 mm letters, baseline 12 mm below the top edge), and two slits 36 mm long, 70 mm apart,
# centred 6 mm below the card's middle, that the barrette's ends tuck behind.

thickness 3 mm

n_bumps = 20
rx = 40 mm
ry = 13 mm

assembly barrette_gift {
    solid barrette {
        oval = Ellipse(center=(0, 0), rx=rx, ry=ry)
        for i in range(n_bumps) {
            bump = Circle(center=(rx * cos(i * 360 deg / n_bumps), ry * sin(i * 360 deg / n_bumps)),
                          radius=3)
        }
        hole stars {
            s1 = Star(center=(-24, 0), points=5, outer_radius=4, inner_radius=1.8)
            s2 = Star(center=(-14, 0), points=5, outer_radius=4, inner_radius=1.8)
            s3 = Star(center=(14, 0), points=5, outer_radius=4, inner_radius=1.8)
            s4 = Star(center=(24, 0), points=5, outer_radius=4, inner_radius=1.8)
        }
        hole rivets {
            r1 = Circle(center=(-33, 0), diameter=2)
            r2 = Circle(center=(33, 0), diameter=2)
        }
        drawing initials {
            t = Text("EM", position=(0, 0), size=8, font="serif:Bold", valign="middle", fill=true)
        }
        Rigid(self)
    }

    solid card {
        body = RoundedRectangle(center=(0, 0), width=110, height=70, corner_radius=5)
        cut slits {
            a = Line((-35, -6 - 18), (-35, -6 + 18))
            b = Line((35, -6 - 18), (35, -6 + 18))
        }
        drawing words {
            t = Text("FOR EMMA", position=(0, 35 - 12), size=5)
        }
        Rigid(self)
    }

    # on the sheet
    RightOf(barrette, card, gap=5)
    AlignCenterY(barrette, card)

    # assembled: the barrette lies on the card, centred 6 mm below its middle
    Place(card, position=(0, 0, 0), face="up")
    Place(barrette, position=(0, -6, 3), face="up")

    # the request's numbers
    assert barrette.oval.rx == 40 mm and barrette.oval.ry == 13 mm, "oval 80 x 26"
    assert len(barrette.bump) == 20, "20 bumps"
    assert barrette.rivets.r2.center.x - barrette.rivets.r1.center.x == 66 mm, "rivets 66 apart"
    assert barrette.stars.s3.center.x - barrette.oval.center.x == 14 mm, "stars at 14"
    assert barrette.stars.s4.center.x - barrette.oval.center.x == 24 mm, "stars at 24"
    assert barrette.initials.bb.width < 2 * (14 mm - 4 mm) - 2 mm, "initials clear of the stars"
    assert card.body.width == 110 mm and card.body.height == 70 mm, "card 110 x 70"
    assert card.slits.b.start.x - card.slits.a.start.x == 70 mm, "slits 70 apart"
    assert card.slits.a.length == 36 mm, "slits 36 long"
    assert card.body.bb.top - card.words.t.position.y == 12 mm, "words 12 below the top"
    assert card.slits.a.length > 2 * ry + 6 mm, "slits longer than the barrette is tall"
}
