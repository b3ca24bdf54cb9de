# Luggage tag: 95 x 55 mm plate with 6 mm rounded corners; a 20 x 5 mm strap slot
# (rounded ends) standing upright, its center 8 mm from the left end; engraved "NAME" and
# "PHONE" labels 4 mm tall with a 50 mm write-on line after each, right of the slot.

param w = 95 mm, min = 80 mm, max = 120 mm
param h = 55 mm, min = 45 mm, max = 70 mm

solid tag {
    body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=6)
    hole strap {
        s = Slot(center=(0, 0), length=20, width=5, rotation=90)
    }
    AlignCenterY(strap, body)
    strap.s.center.x == body.bb.left + 8 mm

    drawing labels {
        name = Text("NAME", position=(-25, 8), size=4, anchor="start")
        name_line = Line((-8, 8), (42, 8))
        phone = Text("PHONE", position=(-25, -10), size=4, anchor="start")
        phone_line = Line((-8, -10), (42, -10))
    }
    assert labels.bb.left > strap.bb.right + 3 mm, "labels clear of the strap slot"
    assert labels.bb.right < body.bb.right - 3 mm, "labels inside the tag"
}
assert tag.body.bb.width == 95 mm and tag.body.bb.height == 55 mm, "tag 95 x 55"
assert tag.strap.s.length == 20 mm and tag.strap.s.width == 5 mm, "strap slot 20 x 5"
assert tag.labels.name_line.length == 50 mm, "write-on lines 50 mm"
