# Request: a seat lid for a 20 litre bucket, so the bucket is a camp stool and a gear box. 6 mm ply.
# The seat is two glued 320 mm discs (12 mm); under them a locating ring 282 OD / 250 ID drops
# inside the bucket's 286 mm mouth. A 100 x 28 mm hand slot (round ends) runs through both discs,
# centred 125 mm from the centre. The top disc has a filled engraved pine tree in the middle (crown
# 60 wide and 70 tall in three tiers, on a 10 x 14 trunk) and "CAMP 14" (14 mm, sans Bold, filled)
# along the rim at the bottom, reading the right way up, their middle on a 270 mm circle.

thickness 6 mm

def seat_disc() -> solid {
    disc = Circle(center=(0, 0), diameter=320)
    hole grip { s = Slot(center=(0, 125), length=100, width=28) }
}

assembly bucket_seat {
    top = seat_disc()
    drawing art {
        crown = Polygon([(0, 40), (18, 16), (9, 16), (24, -6), (13, -6), (30, -30), (0, -30)],
                        mirror="y", fill=true)
        trunk = Rectangle(center=(0, -37), width=10, height=14, fill=true)
        ring = Circle(center=(0, 0), diameter=270, construction=true)
        word = Text("CAMP 14", along=ring, size=14, font="sans:Bold", fill=true, flip=true,
                    valign="middle")
    }
    CutInto(art, top)
    bottom = seat_disc()
    solid ring {
        rim = Circle(center=(0, 0), diameter=282)
        hole inner { c = Circle(center=(0, 0), diameter=250) }
    }

    RightOf(bottom, top, gap=5)
    AlignTop(bottom, top)
    Below(ring, top, gap=5)
    AlignLeft(ring, top)

    Place(ring, position=(0, 0, 0))
    Place(bottom, position=(0, 0, 6))
    Place(top, position=(0, 0, 12))

    assert top.disc.diameter == 320 mm, "seat 320"
    assert ring.rim.diameter == 282 mm and ring.inner.c.diameter == 250 mm, "ring 282 / 250"
    assert ring.rim.diameter < 286 mm, "ring drops inside the 286 mouth"
    assert top.grip.s.length == 100 mm and top.grip.s.width == 28 mm, "hand slot 100 x 28"
    assert top.grip.s.center.y - top.disc.center.y == 125 mm, "slot 125 from the centre"
    assert art.crown.bb.width == 60 mm and art.crown.bb.height == 70 mm, "crown 60 x 70"
    assert art.trunk.width == 10 mm and art.trunk.height == 14 mm, "trunk 10 x 14"
    assert art.trunk.bb.top == art.crown.bb.bottom, "trunk under the crown"
    assert distance(art.word, top.grip) >= 5 mm, "words clear of the hand slot"
    assert art.word.bb.bottom - top.disc.bb.bottom >= 5 mm, "words inside the rim"
}
