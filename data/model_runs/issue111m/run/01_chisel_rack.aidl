# Workshop chisel rack shelf, 6 mm plywood: a board 300 x 70 mm with 6 mm corner
# radii; six chisel slots 14 mm wide, 35 mm deep from the front (bottom) edge, round
# ended, 45 mm apart and centred on the board; each chisel's width (6, 8, 10, 12, 16,
# 20) engraved 5 mm tall, 6 mm behind the end of its slot; three 4.5 mm screw holes
# 10 mm from the back edge, at x = -90, 0, 90 from the middle, countersunk 9 mm.

thickness 6 mm

param pitch = 45 mm, min = 35 mm, max = 48 mm
sizes = [6, 8, 10, 12, 16, 20]

solid shelf {
    board = RoundedRectangle(center=(0, 0), width=300, height=70, corner_radius=6)

    hole slot {
        s = Slot(start=(-2.5 * pitch, -50), end=(-2.5 * pitch, -7), width=14)
    }
    slots = LinearPattern(slot, 6, (pitch, 0))

    drawing labels {
        for i in range(6) {
            t = Text(str(sizes[i]), ((i - 2.5) * pitch, 6), size=5)
        }
    }

    hole screw {
        for i in range(3) {
            c = Circle(center=((i - 1) * 90, 25), diameter=4.5)
        }
    }
    Countersink(screw, diameter=9 mm)

    assert board.width == 300 mm, "board 300 wide"
    assert board.height == 70 mm, "board 70 deep"
    assert len(slots) == 6, "six slots"
    assert slots[0].s.width == 14 mm, "slots 14 wide"
    assert slots[0].s.bb.top - board.bb.bottom == 35 mm, "slots 35 deep from the front edge"
    assert slots[1].s.center.x - slots[0].s.center.x == 45 mm, "slots 45 apart"
    assert (slots[0].s.center.x + slots[5].s.center.x) / 2 == board.center.x, "slots centred"
    assert labels.t[0].position.y - slots[0].s.bb.top == 6 mm, "labels 6 behind the slot ends"
    assert labels.t[0].size == 5 mm, "labels 5 tall"
    assert len(screw.c) == 3, "three screws"
    assert screw.c[0].diameter == 4.5 mm, "4.5 mm screw holes"
    assert board.bb.top - screw.c[1].center.y == 10 mm, "screws 10 from the back edge"
    assert screw.c[2].center.x - board.center.x == 90 mm, "outer screws at 90 mm"
}
