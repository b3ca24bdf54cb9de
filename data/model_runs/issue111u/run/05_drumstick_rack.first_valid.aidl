# Music: a drumstick rack shelf, 6 mm plywood, screwed onto a wall bracket. Plate 200 x 60 mm,
# corners R6. Four pairs of 17 mm holes for the sticks to hang through: holes of a pair 22 mm
# apart, pairs 45 mm apart centre to centre, the row centred left-right with its centres 8 mm
# behind (above) the plate's centre line. Two 4 mm screw holes countersunk to 8 mm, 10 mm in from
# the left and right ends and 12 mm in from the front (bottom) edge. "DRUMS" in sans Bold outline
# letters 8 mm tall engraved, centred, baseline 5 mm above the front edge.

thickness 6 mm

param pairs = 4, min = 2, max = 4
param stick_hole = 17 mm, min = 15 mm, max = 19 mm
param pair_pitch = 45 mm, min = 40 mm, max = 48 mm

solid rack {
    plate = RoundedRectangle(center=(0, 0), width=200, height=60, corner_radius=6)

    hole pair {
        a = Circle(center=(-11, 8), diameter=stick_hole)
        b = Circle(center=(11, 8), diameter=stick_hole)
    }
    row = LinearPattern(pair, pairs, (pair_pitch, 0))
    (row[0].bb.center_x + row[pairs - 1].bb.center_x) / 2 == plate.bb.center_x
    row[0].a.center.y == plate.bb.center_y + 8 mm

    hole screws {
        l = Circle(center=(-90, -18), diameter=4)
        r = Circle(center=(90, -18), diameter=4)
    }
    Countersink(screws, diameter=8 mm)

    drawing name {
        word = Text("DRUMS", (0, -25), size=8, font="sans:Bold")
    }

    assert plate.bb.width == 200 mm and plate.bb.height == 60 mm, "plate 200 x 60"
    assert len(row) == 4, "four pairs"
    assert row[0].b.center.x - row[0].a.center.x == 22 mm, "pair holes 22 apart"
    assert row[1].a.center.x - row[0].a.center.x == 45 mm, "pairs 45 apart"
    assert row[0].a.diameter == 17 mm, "17 mm holes"
    assert screws.l.center.x - plate.bb.left == 10 mm, "left screw 10 in"
    assert plate.bb.right - screws.r.center.x == 10 mm, "right screw 10 in"
    assert screws.l.center.y - plate.bb.bottom == 12 mm, "screws 12 from the front"
    assert name.word.position.y - plate.bb.bottom == 5 mm, "baseline 5 up"
    assert row[3].b.bb.right < screws.r.center.x - 2 mm, "sticks clear the screws"
}
