# Request: a swallow brooch as a gift, on its own gift card. The bird is about 62 mm from
# beak to tail tip, flying left, with a forked tail and one long swept wing raised behind
# the head; cut from 3 mm walnut ply with the eye and a beak line engraved. A 2 mm blue
# acrylic wing is glued on top, the wing's outline inset 1.5 mm, with three feather lines
# engraved. The brooch pin is glued on the back. The card is 1.5 mm ply, 70 x 90 mm with R4
# corners, two 1.6 mm holes 20 mm apart 5 mm above its middle for the pin to go through,
# and "for you" engraved filled (serif, 7 mm) with its middle 30 mm below the card's middle.

# the body outline: beak tip, head, back, tail (upper tip, notch, lower tip), belly, throat
BODY = [(-30, 4), (-22, 9), (-8, 8), (12, 4), (32, 12), (18, 0), (30, -9), (10, -4),
        (-8, -7), (-22, -3)]
# the wing: root front, leading edge, tip, trailing edge, root rear
WING = [(-10, 6), (-2, 20), (22, 30), (8, 16), (4, 5)]

assembly swallow_brooch {
    solid bird {
        thickness 3 mm
        body = Spline(BODY, closed=true, corners=[0, 4, 5, 6])
        wing = Spline(WING, closed=true, corners=[2])
        drawing details {
            eye = Circle(center=(-21, 5), radius=1)
            beak = Line((-30, 4), (-25, 4))
        }
    }

    solid blue_wing {
        thickness 2 mm
        outline = Spline(WING, closed=true, corners=[2], construction=true)
        overlay = Inset(outline, 1.5)
        drawing feathers {
            f1 = Line((0, 10), (14, 24))
            f2 = Line((3, 9), (15, 21))
            f3 = Line((6, 8), (14, 17))
        }
    }

    solid card {
        thickness 1.5 mm
        board = RoundedRectangle(center=(0, 0), width=70, height=90, corner_radius=4)
        hole pin {
            a = Circle(center=(-10, 5), diameter=1.6)
            b = Circle(center=(10, 5), diameter=1.6)
        }
        drawing words {
            t = Text("for you", position=(0, -30), size=7, font="serif", valign="middle", fill=true)
        }
    }

    # flat on the sheet
    RightOf(blue_wing, bird, gap=5)
    AlignTop(blue_wing, bird)
    RightOf(card, blue_wing, gap=5)
    AlignTop(card, bird)

    # in 3D: the card flat, the bird on it over the pin holes, the wing on the bird
    Place(card, position=(0, 0, 0), face="up")
    Place(bird, on=card, position=(0, 5))
    Place(blue_wing, on=bird, position=(0, 0))

    assert bird.body.points[4].x - bird.body.points[0].x == 62 mm, "62 mm beak to tail tip"
    assert card.board.width == 70 mm and card.board.height == 90 mm, "70 x 90 card"
    assert card.pin.b.center.x - card.pin.a.center.x == 20 mm, "pin holes 20 apart"
    assert card.pin.a.center.y - card.board.center.y == 5 mm, "pin holes 5 above the middle"
    assert card.pin.a.diameter == 1.6 mm, "1.6 mm pin holes"
    assert card.board.center.y - card.words.t.position.y == 30 mm, "words 30 below the middle"
    assert blue_wing.overlay.bb.top <= bird.wing.bb.top - 1.5 mm, "the acrylic wing inset"
    assert distance(blue_wing.feathers, blue_wing.overlay) >= 0 mm, "feathers on the wing"
}
