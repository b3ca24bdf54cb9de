# Wrench-size gauge plate: a 150 x 50 mm plate with 5 mm rounded corners and
# six round holes of 6, 8, 10, 12, 14 and 16 mm in a row, centers 23 mm apart,
# the row centered left-to-right with its centers 7 mm above the plate's
# center; under each hole its size engraved ("6" ... "16"), 5 mm tall, the
# label's top 3 mm below the hole.

sizes = [6, 8, 10, 12, 14, 16]
param pitch = 23 mm, min = 20 mm, max = 24 mm

solid gauge {
    body = RoundedRectangle(center=(0, 0), width=150, height=50, corner_radius=5)
    for i in range(6) {
        hole h { c = Circle(center=((i - 2.5) * pitch, 7), diameter=sizes[i]) }
        drawing label { t = Text(str(sizes[i]), position=((i - 2.5) * pitch, -10), size=5, valign="top") }
        At(h.c.center, body.center, dx=(i - 2.5) * pitch, dy=7)
        At(label.t.position, h.c.bottom, dy=-3)
    }

    assert len(h) == 6 and len(label) == 6, "six labelled holes"
    assert h[5].c.diameter == 16 mm and h[0].c.diameter == 6 mm, "hole sizes"
    assert label[5].bb.bottom > body.bb.bottom + 3 mm, "labels stay on the plate"
}
