# Bathroom: a bathtub caddy board, 6 mm plywood, 560 x 180 mm with R15 corners. A wine-glass
# holder at the right end: a 20 mm round hole centred 220 mm right of the board's centre and
# 50 mm above its front (bottom) edge, opened to the front edge by a 12 mm wide throat. A phone
# slot 90 x 10 mm (long side along the board) centred 100 mm right of centre, 40 mm from the
# back (top) edge. Ten drain slots 50 x 6 mm standing across the board, 15 mm apart, the group
# centred 120 mm left of the board's centre and on its middle line. "RELAX" engraved (filled
# letters, sans Bold, 20 mm) centred 100 mm right of centre, 20 mm below the middle line.
units mm
thickness 6 mm

solid caddy {
    board = RoundedRectangle(center=(0, 0), width=560, height=180, corner_radius=15)

    hole glass {
        throat = Rectangle(center=(220, -66), width=12, height=52)
        ring = Circle(center=(220, -40), diameter=20)
    }
    hole phone {
        s = Rectangle(center=(100, 50), width=90, height=10)
    }
    hole drain {
        s = Slot(center=(-187.5, 0), length=50, width=6, rotation=90)
    }
    drains = LinearPattern(drain, 10, (15, 0))

    drawing label {
        word = Text("RELAX", (100, -20), size=20, font="sans:Bold", fill=true, valign="middle")
    }

    assert board.bb.width == 560 mm and board.bb.height == 180 mm, "board 560 x 180"
    assert glass.ring.diameter == 20 mm, "20 mm glass hole"
    assert glass.ring.center.x - board.center.x == 220 mm, "glass hole 220 right of centre"
    assert glass.ring.center.y - board.bb.bottom == 50 mm, "glass hole 50 above the front edge"
    assert glass.throat.bb.width == 12 mm, "12 mm throat"
    assert glass.throat.bb.bottom <= board.bb.bottom, "throat opens through the front edge"
    assert phone.s.bb.width == 90 mm and phone.s.bb.height == 10 mm, "phone slot 90 x 10"
    assert phone.s.center.x - board.center.x == 100 mm, "phone slot 100 right of centre"
    assert board.bb.top - phone.s.center.y == 40 mm, "phone slot 40 from the back edge"
    assert len(drains) == 10, "ten drain slots"
    assert drains[0].s.bb.height == 50 mm and drains[0].s.bb.width == 6 mm, "drain slots 50 x 6"
    assert drains[1].s.center.x - drains[0].s.center.x == 15 mm, "15 mm apart"
    assert (drains[0].s.center.x + drains[9].s.center.x) / 2 - board.center.x == -120 mm, "group 120 left of centre"
    assert drains[0].s.center.y == board.center.y, "on the middle line"
    assert label.word.size == 20 mm, "RELAX 20 mm"
    assert label.word.center.x - board.center.x == 100 mm, "RELAX 100 right of centre"
    assert label.word.position.y - board.center.y == -20 mm, "RELAX 20 below the middle line (valign middle)"
}
