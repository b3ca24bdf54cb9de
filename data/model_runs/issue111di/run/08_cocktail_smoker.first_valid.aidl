# Request (gifts): a cocktail smoker top for my brother's birthday (he loves an old
# fashioned). It sits on a rocks glass: wood chips burn on a 32 mm stainless mesh disc in a
# little chimney and the smoke drops through into the glass. 6 mm walnut ply, glued stack:
# a base disc 100 mm across with a 20 mm hole in the middle; on it a chimney of three rings
# 50 mm across: the lowest with a 32.5 mm bore that seats the mesh disc, the two above with
# a 28 mm bore that holds it down. The base's top is engraved: JAMES over the top and
# EST. 1990 under the bottom, both in bold sans 6 mm tall, filled, their middles on a
# circle of radius 37, both reading the right way up, and two rings of line at radius 30
# and 46 framing them.

thickness 6 mm

def chimney_ring(bore=28 mm) -> solid {
    rim = Circle(center=(0, 0), diameter=50)
    hole h { c = Circle(center=(0, 0), diameter=bore) }
}

assembly cocktail_smoker {
    solid base {
        disc = Circle(center=(0, 0), diameter=100)
        hole smoke { c = Circle(center=(0, 0), diameter=20) }
        drawing art {
            path = Circle(center=(0, 0), radius=37, construction=true)
            name = Text("JAMES", along=path, size=6, font="sans:Bold", fill=true,
                        valign="middle")
            year = Text("EST. 1990", along=path, size=6, font="sans:Bold", fill=true,
                        valign="middle", flip=true)
            inner = Circle(center=(0, 0), radius=30)
            outer = Circle(center=(0, 0), radius=46)
        }
        assert disc.diameter == 100 mm, "base 100 across"
        assert smoke.c.diameter == 20 mm, "20 mm smoke hole"
        assert art.name.bb.top < art.outer.center.y + 46 mm, "JAMES inside the outer ring"
        assert art.year.bb.bottom > art.outer.center.y - 46 mm, "EST. 1990 inside the outer ring"
    }

    seat = chimney_ring(bore=32.5 mm)
    for i in range(2) {
        ring = chimney_ring()
    }

    RightOf(seat, base, gap=8)
    AlignTop(seat, base)
    RightOf(ring[0], base, gap=8)
    Below(ring[0], seat, gap=8)
    RightOf(ring[1], ring[0], gap=8)
    AlignTop(ring[1], ring[0])

    # 3D: the glue-up
    Place(base, position=(0, 0, 0), face="up")
    Place(seat, position=(0, 0, 6), face="up")
    Place(ring[0], position=(0, 0, 12), face="up")
    Place(ring[1], position=(0, 0, 18), face="up")

    assert seat.rim.diameter == 50 mm, "chimney 50 across"
    assert seat.h.c.diameter == 32.5 mm, "mesh seat 32.5"
    assert ring[0].h.c.diameter == 28 mm, "upper bores 28"
    assert len(ring) + 1 == 3, "three chimney rings"
    # the chimney stands inside the inner engraved ring
    assert seat.rim.diameter / 2 < 30 mm, "chimney inside the engraving"
}
