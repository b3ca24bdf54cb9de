# Request (toys): a dress-up sheriff's badge for a child, two layers of 3 mm ply glued
# together (a brooch pin glued on the back).
# - back layer: a six-pointed star, tips 40 mm from the centre, notches 22 mm, each tip
#   ending in a ball 10 mm across centred on the tip.
# - front layer: a disc 46 mm across glued on the star's centre; engraved: a rim ring
#   2 mm in from its edge, "SHERIFF" over the top and "DEPUTY MAX" under the bottom,
#   both 5 mm bold serif capitals filled, reading left to right, their middles on a
#   17.5 mm radius; a filled five-pointed star 18 mm across its tips in the middle.
thickness 3 mm

assembly badge {
    solid back {
        star = Star(center=(0, 0), points=6, outer_radius=40, inner_radius=22)
        ball = Circle(center=(0, 40), diameter=10)
        balls = CircularPattern(ball, 6, star.center)
    }

    solid front {
        disc = Circle(center=(0, 0), diameter=46)
        drawing face {
            rim = Circle(center=(0, 0), radius=23 - 2)
            ring = Circle(center=(0, 0), radius=17.5, construction=true)
            top_word = Text("SHERIFF", along=ring, size=5, valign="middle", font="serif:Bold",
                            fill=true)
            bottom_word = Text("DEPUTY MAX", along=ring, size=5, valign="middle", flip=true,
                               font="serif:Bold", fill=true)
            mark = Star(center=(0, 0), points=5, outer_radius=9, inner_radius=3.6, fill=true)
        }
    }

    RightOf(front, back, gap=10)
    AlignCenterY(front, back)
    # assembled: the disc glued on the star's centre
    Place(front, on=back, position=(0, 0))

    assert len(balls) == 6, "a ball on each of the six tips"
    assert distance(balls[1].center, back.star.center) == 40 mm, "tips 40 mm out"
    assert back.star.inner_radius == 22 mm, "notches at 22 mm"
    assert balls[0].diameter == 10 mm, "balls 10 across"
    assert front.disc.diameter == 46 mm, "disc 46 across"
    assert front.disc.radius - front.face.rim.radius == 2 mm, "rim 2 mm in"
    assert front.face.mark.outer_radius * 2 == 18 mm, "centre star 18 across"
    # the words stay inside the rim ring
    assert front.face.top_word.bb.top <= front.face.rim.bb.top - 0.5 mm, "SHERIFF clear of the rim"
    assert front.face.bottom_word.bb.bottom >= front.face.rim.bb.bottom + 0.5 mm,
        "DEPUTY MAX clear of the rim"
    # the disc covers the notches, so only the six points show round it
    assert front.disc.radius > back.star.inner_radius, "disc hides the notches"
}
