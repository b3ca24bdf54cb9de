# Key rack plate: 200 x 70 mm, 8 mm rounded corners; five hook holes of 6 mm diameter
# in a row, 36 mm apart, centred, 18 mm above the bottom edge; the name "SMITH"
# engraved 10 mm tall, centred, above the hooks; two 4 mm screw holes, 10 mm in from
# the left and right edges, at mid height.
param w = 200 mm, min = 160 mm, max = 300 mm
param h = 70 mm, min = 50 mm, max = 100 mm
param pitch = 36 mm, min = 25 mm, max = 40 mm
thickness 4 mm

solid rack {
    body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=8)
    hole hook { c = Circle(center=(-72, -17), diameter=6) }
    hooks = LinearPattern(hook, 5, (pitch, 0))
    At(hooks[2].c.center, body.bb.bottom_left, dx=w / 2, dy=18)
    hole screw_l { c = Circle(center=(-90, 0), diameter=4) }
    hole screw_r { c = Circle(center=(90, 0), diameter=4) }
    At(screw_l.c.center, body.bb.bottom_left, dx=10, dy=h / 2)
    At(screw_r.c.center, body.bb.bottom_right, dx=-10, dy=h / 2)
    drawing name {
        t = Text("SMITH", (0, 10), size=10, valign="middle")
    }
    AlignCenterX(name, body)
    name.t.position.y == body.center.y + 10
    assert len(hooks) == 5, "five hooks"
    assert hooks[1].c.center.x - hooks[0].c.center.x == 36 mm, "36 mm apart"
    assert name.bb.bottom > hooks[0].bb.top + 3 mm, "name clear of the hooks"
}
