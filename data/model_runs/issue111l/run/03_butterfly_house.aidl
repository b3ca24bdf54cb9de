# Garden butterfly house front: a house-shaped panel 140 mm wide, walls 200 mm tall, a
# gable roof to a point 260 mm above the bottom edge, 6 mm plywood; three vertical
# entry slots 12 x 90 mm (round ends), 35 mm apart, centred across, their centres 90 mm
# above the bottom edge; a 6 mm hanging hole 25 mm below the apex; "BUTTERFLIES"
# engraved 8 mm tall, centred, 20 mm above the bottom edge.

thickness 6 mm

solid front {
    house = Polygon([(-70, 0), (70, 0), (70, 200), (0, 260), (-70, 200)])

    hole entry {
        s = Slot(center=(-35, 90), length=90, width=12, rotation=90)
    }
    entries = LinearPattern(entry, 3, (35, 0))
    (entries[0].s.center.x + entries[2].s.center.x) / 2 == house.bb.center_x
    entry.s.center.y == house.bb.bottom + 90

    hole hang {
        c = Circle(center=(0, 235), diameter=6)
    }
    AlignCenterX(hang, house)
    hang.c.center.y == house.bb.top - 25

    drawing label {
        word = Text("BUTTERFLIES", (0, 20), size=8)
    }
    AlignCenterX(label, house)
    label.word.position.y == house.bb.bottom + 20

    assert house.bb.width == 140 mm, "140 wide"
    assert house.bb.height == 260 mm, "apex 260 above the bottom"
    assert len(entries) == 3, "three slots"
    assert entries[0].s.width == 12 mm and entries[0].s.length == 90 mm, "12 x 90 slots"
    assert entries[1].s.center.x - entries[0].s.center.x == 35 mm, "35 apart"
    assert entries[1].s.center.x == house.bb.center_x, "centred"
    assert entries[0].s.center.y - house.bb.bottom == 90 mm, "90 up"
    assert entries[0].bb.height == 90 mm, "vertical"
    assert hang.c.diameter == 6 mm, "6 mm hole"
    assert house.bb.top - hang.c.center.y == 25 mm, "25 below the apex"
    assert label.word.size == 8 mm, "8 mm text"
    assert label.word.position.y - house.bb.bottom == 20 mm, "20 above the bottom"
    assert label.bb.top < entries[0].bb.bottom, "text under the slots"
}
