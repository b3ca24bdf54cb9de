# Workshop pliers rack: a 200 x 70 mm plate, 6 mm plywood, corners R5, screwed to the wall.
# Five U-notches from the top edge hold pliers by the joint: 12 mm wide, 30 mm deep,
# round-bottomed, 35 mm apart, centred on the plate. Two 4.5 mm screw holes 12 mm from the
# left and right ends, 15 mm above the bottom, countersunk 9 mm. "PLIERS" engraved 6 mm tall,
# centred, 8 mm above the bottom edge.

thickness 6 mm
param notch_w = 12 mm, min = 8 mm, max = 16 mm
param notch_depth = 30 mm, min = 20 mm, max = 40 mm
param pitch = 35 mm, min = 30 mm, max = 38 mm

solid rack {
    body = RoundedRectangle(center=(0, 0), width=200, height=70, corner_radius=5)

    hole notch {
        s = Slot(center=(-70, 30), length=notch_depth + 10, width=notch_w, rotation=90)
    }
    notches = LinearPattern(notch, 5, (pitch, 0))
    # the notch runs notch_depth into the plate, its top pokes out past the edge
    notch.s.bb.bottom == body.bb.top - notch_depth
    notch.s.center.x == body.center.x - 2 * pitch

    hole screw {
        c = Circle(center=(-88, -20), diameter=4.5)
    }
    other_screw = Mirrored(screw, about=Line((0, -40), (0, 40), construction=true))
    screw.c.center.x == body.bb.left + 12
    screw.c.center.y == body.bb.bottom + 15
    Countersink([screw, other_screw], diameter=9)

    drawing label {
        word = Text("PLIERS", (0, -27), size=6)
    }
    AlignCenterX(label, body)
    label.bb.bottom == body.bb.bottom + 8

    assert body.bb.width == 200 mm, "plate 200 wide"
    assert body.bb.height == 70 mm, "plate 70 tall"
    assert len(notches) == 5, "five notches"
    assert body.bb.top - notches[4].s.bb.bottom == 30 mm, "notches 30 deep"
    assert notches[1].s.center.x - notches[0].s.center.x == 35 mm, "35 apart"
    assert abs((notches[0].s.center.x + notches[4].s.center.x) / 2 - body.center.x) < 0.01, "centred"
    assert screw.c.center.x - body.bb.left == 12 mm, "screw 12 from the left"
    assert body.bb.right - other_screw.c.center.x == 12 mm, "screw 12 from the right"
    assert screw.c.center.y - body.bb.bottom == 15 mm, "screw 15 up"
    assert label.bb.bottom - body.bb.bottom == 8 mm, "label 8 up"
}
