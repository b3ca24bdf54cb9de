# Workshop: a spray-can shelf that drops onto two wall brackets. Plate 300 x 100 mm,
# corner radius 6 mm, 3 mm plywood. Three 68 mm holes for the cans, 82 mm apart
# (centre to centre), the row centred on the plate, the hole centres 45 mm below the
# back (top) edge. Two 4 mm screw holes countersunk 8 mm, 12 mm from each end, centred
# in height. "PAINT" engraved 6 mm tall, centred in the strip below the middle can hole.

thickness 3 mm

param can_d = 68 mm, min = 50 mm, max = 72 mm
param pitch = 82 mm, min = 75 mm, max = 90 mm

solid shelf {
    body = RoundedRectangle(center=(0, 0), width=300, height=100, corner_radius=6)

    hole can {
        c = Circle(center=(-pitch, 5), diameter=can_d)
    }
    cans = LinearPattern(can, 3, (pitch, 0))
    # the row is centred; the centres 45 mm below the top edge
    cans[1].c.center.x == body.center.x
    VerticalDistance(cans[0].c.center, body.top.midpoint, 45)

    hole screw {
        c = Circle(center=(-138, 0), diameter=4)
    }
    other_screw = Mirrored(screw, about=Line((0, -60), (0, 60), construction=true))
    HorizontalDistance(body.left.midpoint, screw.c.center, 12)
    AlignCenterY(screw, body)
    Countersink([screw, other_screw], diameter=8)

    drawing label {
        word = Text("PAINT", (0, -39.5), size=6, valign="middle")
    }
    AlignCenterX(label, body)
    label.word.position.y == (body.bb.bottom + cans[1].bb.bottom) / 2

    assert body.width == 300 mm and body.height == 100 mm, "plate 300 x 100"
    assert len(cans) == 3, "three can holes"
    assert cans[0].c.diameter == 68 mm, "68 mm can holes"
    assert cans[1].c.center.x - cans[0].c.center.x == 82 mm, "82 mm apart"
    assert cans[2].c.center.x - cans[1].c.center.x == 82 mm, "82 mm apart"
    assert body.bb.top - cans[2].c.center.y == 45 mm, "45 mm below the back edge"
    assert screw.c.diameter == 4 mm, "4 mm screws"
    assert screw.c.center.x - body.bb.left == 12 mm, "12 mm from the left end"
    assert body.bb.right - other_screw.c.center.x == 12 mm, "12 mm from the right end"
    assert other_screw.bb.left > cans[2].bb.right + 2 mm, "countersink clear of the can hole"
    assert label.word.size == 6 mm, "6 mm text"
    assert label.bb.bottom > body.bb.bottom + 3 mm, "text inside the plate"
    assert label.bb.top < cans[1].bb.bottom - 3 mm, "text clear of the hole"
}
