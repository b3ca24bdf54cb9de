# Request (toys): an animal-stacking balance game for my nephew, 6 mm poplar ply. Four chunky
# animal silhouettes with round, smooth outlines and no thin bits a child could snap off:
# an elephant (about 115 x 75, trunk down, a little tail, ear engraved, 5 mm eye hole),
# a turtle (about 100 x 42, domed shell with an engraved hexagon, 3.6 mm eye), a sitting
# bear (60 x 88 with round ears, engraved snout, two 4 mm eye holes) and a bird (about 76 x 50
# on a 28 mm foot bar, engraved wing, 3.6 mm eye). They stack on a 220 x 45 half-oval hill
# with a flat bottom and "ARCHIE'S ZOO" engraved filled, 12 mm letters.

thickness 6 mm

assembly zoo {
    solid hill {
        mound = Intersect(Ellipse(center=(0, 0), rx=110, ry=45),
                          Rectangle(bottom_left=(-110, 0), width=220, height=45))
        drawing name {
            t = Text("ARCHIE'S ZOO", position=(0, 14), size=12, font="sans:Bold", fill=true)
        }
        Fixed(self)
    }

    solid elephant {
        body = Ellipse(center=(0, 45), rx=40, ry=27)
        head = Circle(center=(38, 55), radius=20)
        trunk = Stroke(Line((52, 45), (60, 12)), width=10)
        tail = Stroke(Line((-39, 46), (-47, 32)), width=4)
        # FIX after the first valid program: the legs were 4, 6 and 2 mm apart (a 2 mm slit
        # between the front legs); now four 12 mm legs 6 mm apart, long enough to meet the body
        for x in [-33, -15, 3, 21] {
            leg = RoundedRectangle(bottom_left=(x, 0), width=12, height=34,
                                   corner_radii=[0, 0, 3, 3])
        }
        hole eye { e = Circle(center=(44, 62), diameter=5) }
        drawing ear { e = Ellipse(center=(30, 55), rx=9, ry=13) }
        Rigid(self)
    }

    solid turtle {
        shell = Intersect(Ellipse(center=(0, 12), rx=38, ry=30),
                          Rectangle(bottom_left=(-40, 12), width=80, height=32))
        # FIX after the first valid program: the rectangle belly, the straight neck band and the
        # tail's corners left 1-2 mm stair-steps in the outline; a flat half-oval belly that
        # meets the shell at its widest, a hull for neck and head, the tail's root inside
        belly = Ellipse(center=(0, 12), rx=38, ry=5)
        head = Hull(Circle(center=(44, 24), radius=9), Circle(center=(30, 14), radius=6))
        tail = Polygon([(-36, 11), (-48, 12.5), (-36, 15)])
        for x in [-28, 16] {
            leg = RoundedRectangle(bottom_left=(x, 0), width=12, height=12,
                                   corner_radii=[0, 0, 3, 3])
        }
        hole eye { e = Circle(center=(47, 27), diameter=3.6) }
        drawing pattern { hex = RegularPolygon(center=(0, 26), radius=9, sides=6) }
        Rigid(self)
    }

    solid bear {
        body = Intersect(Circle(center=(0, 28), radius=30),
                         Rectangle(bottom_left=(-30, 0), width=60, height=60))
        head = Circle(center=(0, 64), radius=18)
        ear_l = Circle(center=(-13, 81), radius=7)
        ear_r = Circle(center=(13, 81), radius=7)
        hole eyes {
            l = Circle(center=(-7, 70), diameter=4)
            r = Circle(center=(7, 70), diameter=4)
        }
        drawing face { snout = Ellipse(center=(0, 60), rx=7, ry=5) }
        Rigid(self)
    }

    solid bird {
        body = Ellipse(center=(0, 22), rx=22, ry=16)
        head = Circle(center=(20, 38), radius=11)
        beak = Polygon([(29, 41), (40, 36), (29, 32)])
        tail = Polygon([(-18, 26), (-36, 40), (-34, 28), (-20, 16)])
        legs = Rectangle(bottom_left=(-5, 2), width=10, height=8)
        foot = RoundedRectangle(bottom_left=(-14, 0), width=28, height=4, corner_radius=2)
        hole eye { e = Circle(center=(23, 41), diameter=3.6) }
        drawing wing { w = Ellipse(center=(-4, 24), rx=12, ry=7, rotation=-15 deg) }
        Rigid(self)
    }

    # on the sheet: the animals in a row above the hill
    Above(elephant, hill, gap=8)
    AlignLeft(elephant, hill)
    RightOf(turtle, elephant, gap=8)
    AlignBottom(turtle, elephant)
    RightOf(bear, turtle, gap=8)
    AlignBottom(bear, elephant)
    RightOf(bird, bear, gap=8)
    AlignBottom(bird, elephant)

    assert hill.mound.bb.width == 220 mm and hill.mound.bb.height == 45 mm, "hill 220 x 45"
    assert bear.bb.width == 60 mm and bear.bb.height == 88 mm, "bear 60 x 88"
    assert elephant.eye.e.diameter == 5 mm, "5 mm eye"
    assert abs(elephant.bb.width - 115 mm) <= 3 mm and abs(elephant.bb.height - 75 mm) <= 3 mm, "elephant about 115 x 75"
    assert abs(turtle.bb.width - 100 mm) <= 3 mm and abs(turtle.bb.height - 42 mm) <= 3 mm, "turtle about 100 x 42"
    assert abs(bird.bb.width - 76 mm) <= 3 mm and abs(bird.bb.height - 50 mm) <= 3 mm, "bird about 76 x 50"
    assert bird.foot.bb.width == 28 mm, "28 mm foot bar"
}
