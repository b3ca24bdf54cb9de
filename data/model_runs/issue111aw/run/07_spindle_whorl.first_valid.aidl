# Request (crafts): a top-whorl drop spindle whorl cut from 6 mm ply: a disc 75 mm across with
# a centre hole for a 3/8 inch dowel shaft, a yarn notch in the rim at 12 o'clock (a V 4 mm
# deep, 60 degrees included), a ring of eight teardrop cut-outs pointing at the centre (a 4 mm
# round tip 16 mm from the centre, an 8 mm round end 24 mm from it, the first at 12 o'clock),
# and "HANDSPUN BY MAREN" engraved 4 mm tall round the bottom of the rim, reading the right
# way up.

units mm
thickness 6 mm

dia = 75 mm
shaft = 0.375 in
notch_d = 4 mm
text_r = 34.5 mm    # the letters hang inside this circle

solid whorl {
    body = Circle(center=(0, 0), diameter=dia)

    hole shaft_hole {
        c = Circle(center=(0, 0), diameter=shaft)
    }

    hole notch {
        v = Polygon([(-(notch_d + 1) * tan(30 deg), dia / 2 + 1), ((notch_d + 1) * tan(30 deg), dia / 2 + 1),
                     (0, dia / 2 - notch_d)])
    }

    hole drop {
        tear = Hull(Circle(center=(0, 16), diameter=4), Circle(center=(0, 24), diameter=8))
    }
    drops = CircularPattern(drop, 8, body.center)

    drawing maker {
        ring = Circle(center=(0, 0), radius=text_r, construction=true)
        name = Text("HANDSPUN BY MAREN", along=ring, flip=true, size=4)
    }

    # the request's own numbers
    assert body.diameter == 75 mm, "whorl 75 across"
    assert abs(shaft_hole.c.diameter - 9.525 mm) < 0.001, "3/8 inch shaft"
    assert len(drops) == 8, "eight teardrops"
    assert abs(body.bb.top - notch.v.points[2].y - 4 mm) < 0.01, "notch 4 deep"
    assert text_r - 4 mm > 24 mm + 4 mm + 1 mm, "the name clear of the teardrops"
    assert text_r < dia / 2 - 2 mm, "the name clear of the rim"
    assert maker.bb.top < 0, "the name round the bottom"
}
