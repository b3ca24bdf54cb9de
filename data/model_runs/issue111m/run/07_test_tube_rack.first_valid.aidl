# Science: test-tube rack, 3 mm acrylic, two plates 200 x 80 mm with 5 mm corner radii,
# held 60 mm apart by four M5 threaded rods: each plate has four 5.2 mm rod holes 8 mm in
# from both edges at its corners. Top plate: 2 rows x 6 columns of 18 mm tube holes, 30
# mm apart both ways, centred on the plate; column numbers 1-6 engraved 4 mm tall over
# the top row (baseline 12 mm above the row's centres) and row letters "A", "B" 5 mm tall
# left of each row (centred 15 mm left of the first hole's centre). Base plate: an 8 mm
# locating hole under each tube (same positions), and its rod holes countersunk 10 mm
# (flat-head screws from below). Cut side by side, 10 mm apart.

thickness 3 mm

param tube_d = 18 mm, min = 12 mm, max = 25 mm
param pitch = 30 mm, min = 22 mm, max = 32 mm
rows = ["A", "B"]

def rack_plate(bore=18 mm, labels=true, sink=false) -> solid {
    body = RoundedRectangle(center=(0, 0), width=200, height=80, corner_radius=5)
    hole tube {
        c = Circle(center=(-2.5 * pitch, -pitch / 2), diameter=bore)
    }
    tubes = GridPattern(tube, 2, 6, (pitch, pitch))
    hole rod {
        c = Circle(center=(-92, -32), diameter=5.2)
    }
    rods = CornerPattern(rod, body, inset=8)
    if sink {
        Countersink(rods, diameter=10 mm)
    }
    if labels {
        drawing numbers {
            for i in range(6) {
                n = Text(str(i + 1), ((i - 2.5) * pitch, pitch / 2 + 12), size=4)
            }
        }
        drawing letters {
            for j in range(2) {
                l = Text(rows[j], (-2.5 * pitch - 15, (0.5 - j) * pitch), size=5, valign="middle")
            }
        }
    }
}

assembly rack {
    top = rack_plate(bore=tube_d, labels=true, sink=false)
    base = rack_plate(bore=8 mm, labels=false, sink=true)
    top.body.center == (0, 0)
    RightOf(base, top, gap=10)
    AlignCenterY(base, top)

    assert top.body.width == 200 mm and top.body.height == 80 mm, "plates 200 x 80"
    assert len(top.tubes) == 12, "2 x 6 tubes"
    assert top.tube.c.diameter == 18 mm, "18 mm tube holes"
    assert top.tubes[1].c.center.x - top.tubes[0].c.center.x == 30 mm, "30 apart across"
    assert top.tubes[6].c.center.y - top.tubes[0].c.center.y == 30 mm, "30 apart up"
    assert (top.tubes[0].c.center.x + top.tubes[11].c.center.x) / 2 == top.body.center.x, "centred across"
    assert (top.tubes[0].c.center.y + top.tubes[11].c.center.y) / 2 == top.body.center.y, "centred up"
    assert len(top.rods) == 4, "four rods"
    assert top.rod.c.diameter == 5.2 mm, "5.2 mm rod holes"
    assert top.rod.c.center.x - top.body.bb.left == 8 mm and top.rod.c.center.y - top.body.bb.bottom == 8 mm, "rods 8 in"
    assert base.tube.c.diameter == 8 mm, "8 mm locating holes"
    assert base.tubes[5].c.center.x - base.body.center.x == top.tubes[5].c.center.x - top.body.center.x, "under the tubes"
    assert top.numbers.n[0].position.y - top.tubes[6].c.center.y == 12 mm, "numbers 12 over the top row"
    assert top.numbers.n[0].size == 4 mm and top.letters.l[0].size == 5 mm, "4 and 5 mm text"
    assert top.tubes[0].c.center.x - top.letters.l[0].position.x == 15 mm, "letters 15 left of the first hole"
    assert base.bb.left - top.bb.right == 10 mm, "10 apart"
}
