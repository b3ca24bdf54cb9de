# Request: a swivel pocket mirror as a gift, three layers of 3 mm walnut ply, 76 mm round.
# The back disc is engraved "with love, Mum" along its top edge (4 mm letters, 30 mm
# from the centre). The middle ring is glued on it and holds a 56 mm round glass mirror in
# a 56.5 mm opening. The lid swings over the mirror on a 3 mm brass rivet: a 3.2 mm hole
# through all three layers 33 mm left of the centre; opposite it the lid has a thumb tab
# reaching 6 mm beyond the round edge. The lid is engraved with the name "Clara" in filled
# serif letters 12 mm tall in the middle, a ring line 30 mm in radius, and the date
# "14.02.2027" (3.5 mm) along the bottom inside the ring. At least 3 mm of wood all round
# the rivet hole.

units mm
thickness 3 mm

dia = 76 mm
pivot = (-33, 0)

assembly mirror {
    solid back {
        disc = Circle(center=(0, 0), diameter=dia)
        hole rivet { c = Circle(center=pivot, diameter=3.2) }
        drawing words {
            arc = Circle(center=(0, 0), radius=30, construction=true)
            t = Text("with love, Mum", along=arc, size=4)
        }
    }
    solid ring {
        disc = Circle(center=(0, 0), diameter=dia)
        hole glass { c = Circle(center=(0, 0), diameter=56.5) }
        hole rivet { c = Circle(center=pivot, diameter=3.2) }
    }
    solid lid {
        round = Circle(center=(0, 0), diameter=dia)
        thumb = Circle(center=(dia / 2 - 2, 0), radius=8)
        shape = Hull(round, thumb)
        hole rivet { c = Circle(center=pivot, diameter=3.2) }
        drawing face {
            name = Text("Clara", position=(0, 0), size=12, font="serif:Bold", valign="middle",
                        fill=true)
            border = Circle(center=(0, 0), radius=30)
            inner = Circle(center=(0, 0), radius=23, construction=true)
            date = Text("14.02.2027", along=inner, size=3.5, flip=true)
        }
    }
    RightOf(ring, back, gap=5)
    AlignCenterY(ring, back)
    RightOf(lid, ring, gap=5)
    AlignCenterY(lid, back)

    Place(back, position=(0, 0, 0), face="up")
    Place(ring, position=(0, 0, 3), face="up")
    Place(lid, position=(0, 0, 6), face="up")

    # the request's numbers
    assert back.disc.diameter == 76 mm and ring.disc.diameter == 76 mm and lid.round.diameter == 76 mm, "76 round"
    assert ring.glass.c.diameter == 56.5 mm, "56.5 opening for the 56 mirror"
    assert back.rivet.c.diameter == 3.2 mm, "3.2 rivet hole"
    assert back.disc.center.x - back.rivet.c.center.x == 33 mm, "rivet 33 left of centre"
    assert lid.shape.bb.right - lid.round.bb.right == 6 mm, "thumb tab 6 beyond the edge"
    assert lid.rivet.c.center.x - lid.rivet.c.radius - lid.round.bb.left >= 3 mm, "3 mm outside the rivet"
    assert (lid.rivet.c.center.x - lid.rivet.c.radius) - (ring.glass.c.center.x - ring.glass.c.radius) >= 0 mm or
        (ring.glass.c.center.x - ring.glass.c.radius) - (ring.rivet.c.center.x + ring.rivet.c.radius) >= 3 mm,
        "3 mm between the rivet and the mirror opening"
    assert lid.face.border.radius == 30 mm, "ring line 30"
    assert abs(lid.face.name.bb.height - 12 mm) <= 3 mm, "name about 12 tall"
    assert lid.face.name.bb.width < 2 * 23 mm - 6 mm, "the name clears the date ring"
}
