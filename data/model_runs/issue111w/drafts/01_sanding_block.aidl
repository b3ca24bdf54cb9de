# Workshop: a laminated sanding block layer, 6 mm plywood, 115 x 70 mm with
# 4 mm rounded corners. Two slits 50 x 3 mm run across it (parallel to the
# short edges), their centres 8 mm in from each short end, to tuck the paper
# into. A 40 mm finger hole in the middle lightens it and lets three layers be
# glued with a grip. "P120" engraved 5 mm high, 10 mm above the bottom edge,
# centred (first draft said 10 mm: the letters then touched the finger hole; 7 mm).

thickness 6 mm
param length = 115 mm, min = 90, max = 150
param width = 70 mm, min = 50, max = 100
param slit_in = 8 mm, min = 6, max = 15

solid block {
    body = RoundedRectangle(center=(0, 0), width=length, height=width, corner_radius=4)
    hole slits {
        left = Slot(center=(-length / 2 + slit_in, 0), length=50, width=3, rotation=90)
        right = Slot(center=(length / 2 - slit_in, 0), length=50, width=3, rotation=90)
    }
    hole grip {
        c = Circle(center=(0, 0), diameter=40)
    }
    drawing label {
        t = Text("P120", (0, -width / 2 + 7), size=5)
    }
    assert body.bb.width == 115 mm, "block 115 long"
    assert body.bb.height == 70 mm, "block 70 wide"
    assert slits.left.center.x - body.bb.left == 8 mm, "left slit 8 in"
    assert body.bb.right - slits.right.center.x == 8 mm, "right slit 8 in"
    assert slits.left.length == 50 mm and slits.left.width == 3 mm, "slit 50 x 3"
    assert grip.c.diameter == 40 mm, "40 mm finger hole"
    assert label.t.position.y - body.bb.bottom == 7 mm, "label 7 above the bottom"
}
