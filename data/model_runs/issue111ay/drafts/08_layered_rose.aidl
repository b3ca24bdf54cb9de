# Request (gifts): a layered wooden rose for Mother's Day, from 3 mm poplar. Four flower layers
# stacked on an 8 mm dowel stem, 80, 62, 44 and 26 mm across the petal tips, each with five
# round petals (each petal a circle 0.22 x the layer's size in radius, its centre 0.28 x the
# size from the middle, over a round core 0.3 x the size in radius), the inner corners
# rounded 1.5 mm, an 8 mm stem hole in the middle, and each layer turned 36 deg from the one
# below so the petals alternate. One leaf slides onto the stem under the flower: a pointed
# leaf blade 60 mm long and 24 mm wide, joined by a 6 mm neck to a ring 18 mm across around
# an 8 mm hole whose centre is 36 mm from the blade's middle; an engraved midrib along the
# blade and "MUM" engraved 5 mm tall above the midrib.

units mm
thickness 3 mm

param stem = 8 mm, min = 6 mm, max = 10 mm

def layer(d=80 mm, turn=0 deg) -> solid {
    core = Circle(center=(0, 0), radius=0.3 * d)
    petal = Circle(center=(0.28 * d * cos(turn + 90 deg), 0.28 * d * sin(turn + 90 deg)),
                   radius=0.22 * d)
    petals = CircularPattern(petal, 5, (0, 0))
    hole bore { c = Circle(center=(0, 0), diameter=stem) }
    Fixed(core)
    Fixed(petal)
    Fixed(bore)
    Fillet(1.5)
    assert len(petals) == 5
    assert distance(petal.center, core.center) + petal.radius == d / 2, "tips on the size"
}

assembly rose {
    outer = layer(d=80 mm, turn=0 deg)
    second = layer(d=62 mm, turn=36 deg)
    third = layer(d=44 mm, turn=72 deg)
    inner = layer(d=26 mm, turn=108 deg)

    solid leaf {
        # a lens 60 x 24: two circles of radius 43.5 whose centres are 63 apart
        blade = Intersect(Circle(center=(0, -31.5), radius=43.5),
                          Circle(center=(0, 31.5), radius=43.5))
        neck = Stroke(Line((-36, 0), (-24, 0)), width=6)
        ring = Circle(center=(-36, 0), diameter=18)
        hole bore { c = Circle(center=(-36, 0), diameter=stem) }
        drawing veins {
            midrib = Line((-26, 0), (27, 0))
            word = Text("MUM", position=(2, 2), size=5)
        }
        Fixed(blade)
        Fixed(ring)
        Fixed(bore)
        Fixed(veins)
        assert blade.bb.width == 60 mm and blade.bb.height == 24 mm
        assert blade.bb.center_x - bore.c.center.x == 36 mm
        assert veins.word.position.y > veins.midrib.start.y
    }

    # flat for cutting: a row of layers, the leaf beside them
    RightOf(second, outer, gap=5)
    RightOf(third, second, gap=5)
    RightOf(inner, third, gap=5)
    RightOf(leaf, inner, gap=5)
    AlignCenterY(second, outer)
    AlignCenterY(third, outer)
    AlignCenterY(inner, outer)
    AlignCenterY(leaf, outer)

    # assembled: the leaf, then the four layers, stacked on the stem
    Place(leaf, position=(36, 0, 0))
    Place(outer, position=(0, 0, 3))
    Place(second, position=(0, 0, 6))
    Place(third, position=(0, 0, 9))
    Place(inner, position=(0, 0, 12))

    assert outer.petal.radius == 0.22 * 80 mm and inner.core.radius == 0.3 * 26 mm
    assert outer.bore.c.diameter == 8 mm
}
