# Garden: shed wall rack for long-handled tools, 6 mm plywood board 300 x 80 mm with
# 6 mm corner radius. Four U-shaped slots open at the bottom edge, 25 mm wide and 40 mm
# deep (round end), 75 mm apart, centred on the board; their mouth corners rounded 3 mm.
# Three 4 mm screw holes 25 mm above the board's centre line, 75 mm apart (middle one
# centred), countersunk 8 mm.
thickness 6 mm

param pitch = 75 mm, min = 60 mm, max = 75 mm

solid rack {
    board = RoundedRectangle(center=(0, 0), width=300, height=80, corner_radius=6)

    hole u {
        s = Slot(start=(-112.5, -50), end=(-112.5, -12.5), width=25)
    }
    us = LinearPattern(u, 4, (pitch, 0))
    # the U reaches 40 mm up from the bottom edge; the slot is centred on the board
    u.s.bb.top == board.bb.bottom + 40 mm
    us[0].s.center.x + us[3].s.center.x == 2 * board.center.x
    Vertical(u.s.start, u.s.end)
    u.s.start.y == board.bb.bottom - 10 mm

    hole screw { c = Circle(center=(-75, 25), diameter=4) }
    screws = LinearPattern(screw, 3, (75, 0))
    screws[1].c.center.x == board.center.x
    screw.c.center.y == board.center.y + 25 mm
    Countersink(screw, diameter=8 mm)

    Fillet(3)

    assert board.width == 300 mm and board.height == 80 mm, "board 300 x 80"
    assert len(us) == 4, "four slots"
    assert us[0].s.width == 25 mm, "slots 25 wide"
    assert us[1].s.center.x - us[0].s.center.x == 75 mm, "slots 75 apart"
    assert us[2].s.bb.top - board.bb.bottom == 40 mm, "40 deep"
    assert len(screws) == 3, "three screws"
}
