# Luggage tag: 90 x 55 mm with 8 mm rounded corners; a strap slot 20 x 5 mm (round ends)
# running up-down, its centre 9 mm from the left edge, at mid-height; "NAME" and "PHONE"
# engraved 4 mm tall, left-aligned 22 mm from the left edge, with a 45 mm writing line
# 2 mm under each, the lines 35 and 18 mm above the bottom edge.
param w = 90 mm, min = 70 mm, max = 120 mm
param h = 55 mm, min = 40 mm, max = 80 mm
thickness 2 mm

solid tag {
    body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=8)
    hole strap { s = Slot(center=(-36, 0), length=20, width=5, rotation=90) }
    At(strap.s.center, body.left.midpoint, dx=9)
    drawing fields {
        name = Text("NAME", (-23, 9.5), size=4, anchor="start")
        name_line = Line((-23, 7.5), (22, 7.5))
        phone = Text("PHONE", (-23, -7.5), size=4, anchor="start")
        phone_line = Line((-23, -9.5), (22, -9.5))
    }
    Rigid(fields)
    At(fields.name_line.start, body.bb.bottom_left, dx=22, dy=35)
    assert fields.name_line.length == 45 mm and fields.phone_line.length == 45 mm, "45 mm lines"
    assert fields.name_line.start.y - fields.phone_line.start.y == 17 mm, "lines 35 and 18 mm up"
    assert strap.s.length == 20 mm and strap.s.width == 5 mm, "strap slot 20 x 5"
    assert fields.bb.right < body.bb.right - 3 mm, "fields on the tag"
}
