# Workshop F-clamp rack: a 300 x 80 mm plate of 6 mm plywood screwed to the wall.
# Five slots 20 mm wide open from the top edge, 45 mm deep with round bottoms,
# 55 mm apart (centred on the plate) for the clamp bars. Two 4.5 mm screw holes,
# 15 mm up from the bottom and 20 mm in from the ends, countersunk 9 mm.
# "CLAMPS" engraved 8 mm tall, centred left-right, baseline 10 mm above the bottom.
# Corners rounded 4 mm.

units mm
thickness 6 mm

param slots = 5, min = 2, max = 5
param pitch = 55 mm, min = 40 mm, max = 60 mm

solid rack {
    body = Rectangle(center=(0, 0), width=300, height=80)

    hole bar_slot {
        # a stadium 20 wide; 10 mm of it stands above the edge so the slot opens out
        s = Slot(center=(-(slots - 1) * pitch / 2, 40 - 45 + 27.5), length=55, width=20, rotation=90)
    }
    row = LinearPattern(bar_slot, slots, (pitch, 0))
    # the slot's round bottom is 45 mm below the top edge
    row[0].s.bb.bottom == body.bb.top - 45
    # the row is centred: the first slot is half the row's span left of the middle
    HorizontalDistance(body.center, row[0].s.center, -(slots - 1) * pitch / 2)

    hole screw {
        c = Circle(center=(-130, -25), diameter=4.5)
    }
    screws = LinearPattern(screw, 2, (260, 0))
    HorizontalDistance(body.bb.bottom_left, screw.c.center, 20)
    VerticalDistance(body.bb.bottom_left, screw.c.center, 15)
    Countersink(screw, diameter=9)

    drawing label {
        t = Text("CLAMPS", (0, -30), size=8)
    }
    AlignCenterX(label, body)
    label.t.position.y == body.bb.bottom + 10

    Fillet(4)

    assert body.bb.width == 300 mm and body.bb.height == 80 mm, "plate 300 x 80"
    assert len(row) == 5, "five slots"
    assert row[0].s.width == 20 mm, "slots 20 mm wide"
    assert body.bb.top - row[0].s.bb.bottom == 45 mm, "slots 45 mm deep"
    assert row[1].s.center.x - row[0].s.center.x == 55 mm, "55 mm apart"
    assert abs((row[0].s.center.x + row[4].s.center.x) / 2 - body.center.x) < 0.01 mm, "row centred"
    assert screws[0].c.diameter == 4.5 mm, "4.5 mm screws"
    assert screws[0].c.center.y - body.bb.bottom == 15 mm, "screws 15 mm up"
    assert screws[0].c.center.x - body.bb.left == 20 mm, "left screw 20 mm in"
    assert body.bb.right - screws[1].c.center.x == 20 mm, "right screw 20 mm in"
    assert label.t.size == 8 mm, "text 8 mm"
}
