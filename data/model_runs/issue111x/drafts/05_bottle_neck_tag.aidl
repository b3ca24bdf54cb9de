# Parties: a New Year's bottle-neck tag, 3 mm birch. Tag 70 mm wide x 110 mm tall, R8
# corners; a 36 mm hole for the bottle's neck, centred across, its centre 28 mm below the
# top edge; "CHEERS" cut right through in sans Bold (stencil, counters held), 12 mm cap
# height but at most 58 mm wide, centred across, its middle 68 mm below the top edge;
# "31.12.2026" engraved 6 mm tall, centred across, its middle 92 mm below the top edge.

thickness 3 mm

solid tag {
    card = RoundedRectangle(center=(0, 0), width=70, height=110, corner_radius=8)

    hole neck {
        c = Circle(center=(0, 27), diameter=36)
    }
    AlignCenterX(neck, card)
    neck.c.center.y == card.bb.top - 28 mm

    hole word {
        t = Text("CHEERS", (0, -13), size=12, font="sans:Bold", valign="middle",
                 max_width=58, stencil=true)
    }
    AlignCenterX(word, card)
    word.bb.center_y == card.bb.top - 68 mm

    drawing date {
        d = Text("31.12.2026", (0, -37), size=6, valign="middle")
    }
    AlignCenterX(date, card)
    date.bb.center_y == card.bb.top - 92 mm
}

assert tag.card.bb.width == 70 mm and tag.card.bb.height == 110 mm, "tag 70 x 110"
assert tag.neck.c.diameter == 36 mm, "36 mm neck hole"
assert tag.bb.top - tag.neck.c.center.y == 28 mm, "neck hole 28 below the top"
assert tag.word.bb.width <= 58 mm, "CHEERS at most 58 wide"
assert tag.bb.top - tag.word.bb.center_y == 68 mm, "CHEERS 68 below the top"
assert tag.word.bb.top < tag.neck.bb.bottom - 3 mm, "CHEERS clear of the neck hole"
assert tag.bb.top - tag.date.bb.center_y == 92 mm, "date 92 below the top"
