# Request: a luthier's string-action card in 3 mm clear acrylic, 120 x 35 mm, three corners
# R3 and the bottom-left corner sharp (it is the zero of the scale). Stood on the 12th fret
# beside a string, the action is read on an engraved scale at the left edge: lines from the
# bottom edge at 0.5 to 4.0 mm every 0.25 mm (15 lines), touching the left edge: 12 mm long at
# whole millimetres, 9 mm at halves, 6 mm at quarters, whole millimetres labelled 1-4 just
# right of their line. A millimetre ruler along the top edge from x = 30 to 110 mm (80 mm):
# ticks 2 mm long, 3.5 mm at 5, 5 mm at 10 with the centimetre numbers 0-8 under them.
# "ACTION @ 12TH FRET" and "mm" engraved, a 5 mm hanging hole 7 mm in from the right end.

thickness 3 mm

card_w = 120 mm
card_h = 35 mm

def tick_len(k) = 12 mm if k % 4 == 2 else (9 mm if k % 2 == 0 else 6 mm)

solid gauge {
    card = RoundedRectangle(bottom_left=(0, 0), width=card_w, height=card_h,
                            corner_radii=[3, 3, 3, 0])
    hole hang { c = Circle(center=(card_w - 7, card_h / 2 - 6), diameter=5) }

    drawing action {
        for k in range(15) {
            line = Line((0, 0.5 + 0.25 * k), (tick_len(k), 0.5 + 0.25 * k))
        }
        # FIX after the first valid program: labels 1.8 mm tall on lines 1 mm apart piled up
        # (W0513 x3) and "1" met the bottom edge (W0516): the whole-millimetre lines now run
        # on as fanned leaders to labels 4 mm apart
        for m in range(1, 5) {
            lead = Line((12, m), (20, 4 * m + 2))
            num = Text(str(m), position=(21, 4 * m + 2), size=2.5, anchor="start",
                       valign="middle")
        }
        unit = Text("mm", position=(21, 23), size=2.2, anchor="start", valign="middle")
    }

    drawing ruler {
        for i in range(81) {
            tick = Line((30 + i, card_h),
                        (30 + i, card_h - (5 if i % 10 == 0 else (3.5 if i % 5 == 0 else 2))))
        }
        for c in range(9) {
            cm = Text(str(c), position=(30 + 10 * c, card_h - 8), size=2.5, valign="middle")
        }
    }

    drawing title {
        words = Text("ACTION @ 12TH FRET", position=(68, 12), size=4, valign="middle")
    }
    Fixed(card)

    assert card.width == 120 mm and card.height == 35 mm
    assert len(action.line) == 15
    assert action.line[0].start.y - card.bb.bottom == 0.5 mm
    assert action.line[14].start.y - card.bb.bottom == 4.0 mm
    assert action.line[2].length == 12 mm and action.line[4].length == 9 mm
    assert action.line[1].length == 6 mm
    assert action.line[0].start.x == card.bb.left, "lines touch the left edge"
    assert len(ruler.tick) == 81
    assert ruler.tick[80].start.x - ruler.tick[0].start.x == 80 mm
    assert ruler.tick[0].start.x - card.bb.left == 30 mm
    assert card.bb.right - hang.c.center.x == 7 mm
    assert hang.c.diameter == 5 mm
}
