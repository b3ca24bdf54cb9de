# Request: a music-stave stencil for my theory pupils, 3 mm clear acrylic, 240 x 90 mm with
# R5 corners. Two staves, each of five slots 1 mm wide and 200 mm long (end to end of the
# pen's travel: slot end centres 200 apart), lines 3 mm apart, starting 10 mm from the left
# edge; upper stave's lines at 14..26 mm above the plate's middle, lower stave's at -16..-4.
# A 20 mm thumb hole on the right, 15 mm in from the right edge, on the middle line.
# Below the staves a row of 12 note-head openings (3.6 x 2.6 mm ellipses turned 20°),
# 8 mm apart from 10 mm in, the first six with a 0.8 mm stem 9.5 mm long rising from the
# head's right side; centre line 30 mm below the middle (28 in the first draft: the stems
# came 1.6 mm from the lower stave, caught by the clearance assert). Engraved: a ruler along the top edge,
# 0 to 22 cm from the left slot end (tick every 5 mm, 3 mm long, 6 mm at each cm, numbered
# 2.5 mm high) and "STAVE STENCIL - 3 mm" (4 mm, single stroke) along the bottom.

thickness 3 mm

plate_w = 240 mm
plate_h = 90 mm
x0 = -plate_w / 2 + 10 mm
line_gap = 3 mm

solid stencil {
    body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=5)
    Fixed(body)
    hole staves {
        for k in range(5) {
            upper = Slot(start=(x0, 14 + k * line_gap), end=(x0 + 200, 14 + k * line_gap), width=1)
            lower = Slot(start=(x0, -16 + k * line_gap), end=(x0 + 200, -16 + k * line_gap), width=1)
        }
    }
    hole thumb {
        c = Circle(center=(plate_w / 2 - 15, 0), diameter=20)
    }
    hole notes {
        for n in range(12) {
            head = Ellipse(center=(x0 + n * 8, -30), rx=1.8, ry=1.3, rotation=20 deg)
        }
        for n in range(6) {
            stem = Slot(start=(x0 + n * 8 + 1.4, -29.5), end=(x0 + n * 8 + 1.4, -20.5), width=0.8)
        }
    }
    drawing ruler {
        for i in range(45) {
            tick = Line((x0 + i * 5, plate_h / 2), (x0 + i * 5, plate_h / 2 - (6 if i % 2 == 0 else 3)))
        }
        for c in range(23) {
            num = Text(str(c), position=(x0 + c * 10, plate_h / 2 - 8.5), size=2.5, valign="middle")
        }
    }
    drawing title {
        t = Text("STAVE STENCIL - 3 mm", position=(0, -39), size=4, valign="middle")
    }

    assert body.bb.width == 240 mm and body.bb.height == 90 mm, "plate 240 x 90"
    assert len(staves.upper) == 5 and len(staves.lower) == 5, "five lines per stave"
    assert staves.upper[1].start.y - staves.upper[0].start.y == 3 mm, "lines 3 apart"
    assert staves.upper[0].width == 1 mm, "slots 1 wide"
    assert distance(staves.upper[0].start, staves.upper[0].end) == 200 mm, "200 mm of travel"
    assert staves.upper[0].start.x - body.bb.left == 10 mm, "10 from the left edge"
    assert body.bb.right - thumb.c.center.x == 15 mm, "thumb hole 15 in"
    assert thumb.c.bb.left - staves.upper[0].bb.right >= 3 mm, "thumb hole clear of the slots"
    assert len(notes.head) == 12 and len(notes.stem) == 6, "12 heads, 6 stems"
    assert distance(ruler, staves) >= 1.5 mm, "ruler clear of the top stave"
    assert distance(notes, staves) >= 2 mm, "note row clear of the bottom stave"
    assert distance(title, notes) >= 1.5 mm, "title clear of the notes"
}
