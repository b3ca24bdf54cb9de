# Request (parties): a cocktail-party plate that also holds your wine glass, 6 mm birch ply:
# an oval 260 x 190 mm; at the right end of its long axis a 9 mm wide entry slot runs in from
# the rim to a 12 mm round seat for the glass's stem, 30 mm in from the rim; all corners of
# the cut rounded 1.5 mm. Engraved: an oval line 12 mm inside the rim, broken for 45 mm round
# the seat where the glass's bowl sits, and "CHEERS!" 8 mm high (bold, filled) centred 70 mm
# below the middle.

units mm
thickness 6 mm

plate_w = 260 mm
plate_h = 190 mm
seat_in = 30 mm
seat_d = 12 mm
entry_w = 9 mm
rim_line = 12 mm
bowl_clear = 45 mm

solid party_plate {
    oval = Ellipse(center=(0, 0), rx=plate_w / 2, ry=plate_h / 2)
    Fixed(oval)
    hole glass {
        seat = Circle(center=(plate_w / 2 - seat_in, 0), diameter=seat_d)
        entry = Rectangle(corner=(plate_w / 2 - seat_in, -entry_w / 2),
                          opposite=(plate_w / 2 + 1, entry_w / 2))
    }
    drawing decor {
        ring = Ellipse(center=(0, 0), rx=plate_w / 2 - rim_line, ry=plate_h / 2 - rim_line)
        hole bowl { c = Circle(center=(plate_w / 2 - seat_in, 0), radius=bowl_clear) }
        word = Text("CHEERS!", position=(0, -70), size=8, font="sans:Bold", fill=true)
    }
    Fillet(1.5)

    assert oval.bb.width == 260 mm and oval.bb.height == 190 mm, "260 x 190 oval"
    assert oval.bb.right - glass.seat.center.x == 30 mm, "seat 30 mm in"
    assert glass.seat.diameter == 12 mm, "12 mm seat"
    assert glass.entry.bb.height == 9 mm, "9 mm entry"
    assert entry_w < seat_d, "the entry is narrower than the seat: the stem stays put"
    assert oval.bb.right - decor.ring.bb.right == 12 mm, "rim line 12 in"
    assert decor.bowl.c.radius == 45 mm, "line broken 45 mm round the seat"
    assert oval.center.y - decor.word.position.y == 70 mm, "CHEERS 70 below the middle"
}
