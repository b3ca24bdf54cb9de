# Request: a layered Remembrance poppy brooch from 3 mm acrylic, about 50 mm across, three
# parts glued in a stack: a green leaf at the back, 45 long x 20 wide (a pointed lens shape)
# with an engraved midrib, poking out to the lower right at -40 degrees from under the
# petals; the red petals: two upper petals 15 mm in radius centred (-10, 8) and (10, 8) and
# two lower ones 13 mm in radius at (-9, -9) and (9, -9), their inner corners rounded 2 mm,
# with "LEST WE FORGET" engraved 3 mm tall round the lower part, reading the right way up,
# on a 15 mm circle; the black centre an 18 mm disc with 12 engraved ridges from 3 to 7.5 mm
# out. A brooch pin is glued on the back of the petals.

thickness 3 mm

assembly poppy {
    solid leaf {
        lens = Intersect(Circle(center=polar((22, -22), 20, 50 deg), radius=30),
                         Circle(center=polar((22, -22), 20, 230 deg), radius=30))
        drawing rib {
            l = Line(start=polar((22, -22), 20, 140 deg), end=polar((22, -22), 18, -40 deg))
        }
        Rigid(self)
    }

    solid petals {
        ul = Circle(center=(-10, 8), radius=15)
        ur = Circle(center=(10, 8), radius=15)
        ll = Circle(center=(-9, -9), radius=13)
        lr = Circle(center=(9, -9), radius=13)
        drawing words {
            ring = Circle(center=(0, 0), radius=15, construction=true)
            t = Text("LEST WE FORGET", along=ring, size=3, flip=true)
        }
        Fillet(radius=2)
        Rigid(self)
    }

    solid centre {
        disc = Circle(center=(0, 0), diameter=18)
        drawing ridges {
            r0 = Line((3, 0), (7.5, 0))
        }
        ridge_set = CircularPattern(ridges.r0, 12, disc.center)
        Rigid(self)
    }

    # on the sheet
    RightOf(petals, leaf, gap=5)
    AlignCenterY(petals, leaf)
    RightOf(centre, petals, gap=5)
    AlignCenterY(centre, petals)

    # the stack: leaf at the back, petals, centre on top
    Place(leaf, position=(0, 0, 0), face="up")
    Place(petals, position=(0, 0, 3), face="up")
    Place(centre, position=(0, 0, 6), face="up")

    # the request's numbers
    assert petals.ul.radius == 15 mm and petals.ll.radius == 13 mm, "petal radii"
    assert centre.disc.diameter == 18 mm, "centre 18"
    assert abs(leaf.lens.bb.width - 45 mm) < 20 mm, "leaf roughly 45 long"
    assert len(ridge_set) == 12, "12 ridges"
    assert petals.words.t.size == 3 mm, "letters 3 tall"
}
