# Dog leash holder (pets). Full sizes: a wall plate 240 x 90 mm with 12 mm corner radii,
# 6 mm ply. Three 12 mm holes for wooden hook pegs, 60 mm apart (the middle one on the
# plate's vertical centre line), their centres 22 mm above the bottom edge. Two screw holes
# 4.5 mm, countersunk 9 mm, 15 mm in from the left and right edges at half the plate's
# height. "WALKIES" engraved 10 mm high, centred across, its middle 20 mm above the plate's
# middle. A paw print cut through on each side of the word, centred 80 mm left and right of
# the centre line at the word's height: a 14 x 11 mm oval pad and four 6 mm toes above it.

units mm
thickness 6 mm

def paw() -> hole {
    pad = Ellipse(center=(0, 0), rx=7, ry=5.5)
    t1 = Circle(center=(-9, 7), diameter=6)
    t2 = Circle(center=(-3.5, 11.5), diameter=6)
    t3 = Circle(center=(3.5, 11.5), diameter=6)
    t4 = Circle(center=(9, 7), diameter=6)
}

solid holder {
    plate = RoundedRectangle(center=(0, 0), width=240, height=90, corner_radius=12)

    hole pegs {
        p = Circle(center=(-60, -23), diameter=12)
    }
    row = LinearPattern(pegs, 3, (60, 0))
    AlignCenterX(row[1], plate)
    row[0].p.center.y == plate.bb.bottom + 22

    hole screws {
        s1 = Circle(center=(-105, 0), diameter=4.5)
        s2 = Circle(center=(105, 0), diameter=4.5)
    }
    screws.s1.center.x == plate.bb.left + 15
    screws.s2.center.x == plate.bb.right - 15
    screws.s1.center.y == plate.center.y
    screws.s2.center.y == plate.center.y
    Countersink(screws, diameter=9)

    drawing label {
        word = Text("WALKIES", position=(0, 20), size=10, valign="middle")
    }
    AlignCenterX(label, plate)
    label.word.position.y == plate.center.y + 20

    left_paw = paw()
    right_paw = paw()
    Rigid(left_paw)
    Rigid(right_paw)
    left_paw.bb.center_x == plate.center.x - 80
    right_paw.bb.center_x == plate.center.x + 80
    left_paw.bb.center_y == label.word.position.y
    right_paw.bb.center_y == label.word.position.y

    assert plate.bb.width == 240 mm and plate.bb.height == 90 mm, "plate 240 x 90"
    assert len(row) == 3, "three pegs"
    assert row[0].p.diameter == 12 mm, "12 mm peg holes"
    assert row[1].p.center.x - row[0].p.center.x == 60 mm, "pegs 60 mm apart"
    assert row[2].p.center.x - row[1].p.center.x == 60 mm, "pegs 60 mm apart"
    assert row[1].p.center.x == plate.bb.center_x, "middle peg on the centre line"
    assert row[2].p.center.y - plate.bb.bottom == 22 mm, "pegs 22 mm above the bottom"
    assert screws.s1.diameter == 4.5 mm, "4.5 mm screws"
    assert screws.s1.center.x - plate.bb.left == 15 mm, "left screw 15 mm in"
    assert plate.bb.right - screws.s2.center.x == 15 mm, "right screw 15 mm in"
    assert label.word.size == 10 mm, "word 10 mm high"
    assert label.word.position.y - plate.bb.center_y == 20 mm, "word 20 mm above middle"
    assert right_paw.bb.center_x - plate.bb.center_x == 80 mm, "paws 80 mm out"
    assert left_paw.pad.rx == 7 mm and left_paw.pad.ry == 5.5 mm, "14 x 11 pad"
    assert label.bb.right < right_paw.bb.left and label.bb.left > left_paw.bb.right, "paws clear of the word"
    assert right_paw.bb.right < screws.s2.center.x - 4.5 mm, "paw clear of the countersink"
}
