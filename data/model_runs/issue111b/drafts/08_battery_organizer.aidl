# Battery organizer top plate, 3 mm plywood: 150 x 100 mm, R5 corners. Left block: 4 rows x
# 3 columns of 15 mm holes for AA cells, 19 mm pitch, block centered at (-35, -8) mm from the
# plate's center; right block: 4 rows x 3 columns of 11 mm holes for AAA cells, 15 mm pitch,
# centered at (38, -8). "AA" and "AAA" engraved 6 mm tall, centered over each block, baseline
# 8 mm above the block's top. Four 3 mm screw holes 6 mm in from the corners.

units mm
thickness 3 mm

solid organizer {
    plate = RoundedRectangle(center=(0, 0), width=150, height=100, corner_radius=5)

    hole aa {
        c = Circle(center=(-35 - 19, -8 - 1.5 * 19), diameter=15)
    }
    aa_cells = GridPattern(aa, 4, 3, 19 mm)

    hole aaa {
        c = Circle(center=(38 - 15, -8 - 1.5 * 15), diameter=11)
    }
    aaa_cells = GridPattern(aaa, 4, 3, 15 mm)

    hole screw {
        c = Circle(center=(-69, -44), diameter=3)
    }
    screws = CornerPattern(screw, plate, inset=6 mm)

    drawing labels {
        aa_t = Text("AA", position=(-35, -8 + 1.5 * 19 + 7.5 + 8), size=6)
        aaa_t = Text("AAA", position=(38, -8 + 1.5 * 15 + 5.5 + 8), size=6)
    }

    assert abs(plate.bb.width - 150 mm) < 0.001 mm and abs(plate.bb.height - 100 mm) < 0.001 mm, "plate 150 x 100"
    assert len(aa_cells) == 12 and len(aaa_cells) == 12, "4 x 3 cells each"
    assert aa.c.diameter == 15 mm and aaa.c.diameter == 11 mm, "AA 15 mm, AAA 11 mm"
    assert abs(aa_cells[1].c.center.x - aa_cells[0].c.center.x - 19 mm) < 0.001 mm, "AA pitch 19 mm"
    assert abs(aaa_cells[1].c.center.x - aaa_cells[0].c.center.x - 15 mm) < 0.001 mm, "AAA pitch 15 mm"
    assert abs(labels.aa_t.position.y - 8 mm - (aa_cells[11].c.center.y + 7.5 mm)) < 0.001 mm, "AA label 8 mm above its block"
    assert len(screws) == 4, "four screw holes"
}
