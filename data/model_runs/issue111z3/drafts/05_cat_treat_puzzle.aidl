# Pets: cat treat puzzle top: a 240 x 150 mm plate of 3 mm acrylic with R8 corners, laid over a tray
# of treats. Twelve 28 mm paw holes in 3 rows x 4 columns, 40 mm apart both ways, the grid centred
# vertically and its centre 25 mm left of the plate's centre. A paw print engraved on the right,
# centred 80 mm right of the plate's centre: a main pad about 30 mm wide and four oval toes above it.
# Two half-round finger notches R10 at the middle of the short edges to lift the plate.

units mm
thickness 3 mm

param rows = 3, min = 2, max = 3
param cols = 4, min = 2, max = 4
param pitch = 40 mm, min = 34, max = 45

solid puzzle {
    plate = RoundedRectangle(center=(0, 0), width=240, height=150, corner_radius=8)

    hole well {
        c = Circle(center=(-25 - 1.5 * pitch, -pitch), diameter=28)
    }
    wells = GridPattern(well, rows, cols, pitch)

    hole notch_left {
        c = Circle(center=(-120, 0), radius=10)
    }
    hole notch_right {
        c = Circle(center=(120, 0), radius=10)
    }

    drawing paw {
        pad = Hull(Circle(center=(80, -14), radius=9), Circle(center=(71, -22), radius=6),
                   Circle(center=(89, -22), radius=6))
        t1 = Ellipse(center=(63, 0), rx=4.5, ry=6.5, rotation=20 deg)
        t2 = Ellipse(center=(74, 8), rx=4.5, ry=6.5, rotation=5 deg)
        t3 = Ellipse(center=(86, 8), rx=4.5, ry=6.5, rotation=-5 deg)
        t4 = Ellipse(center=(97, 0), rx=4.5, ry=6.5, rotation=-20 deg)
    }

    assert plate.bb.width == 240 mm and plate.bb.height == 150 mm, "plate 240 x 150"
    assert len(wells) == 12, "12 holes"
    assert well.c.diameter == 28 mm, "28 mm holes"
    assert wells[1].c.center.x - wells[0].c.center.x == 40 mm, "columns 40 apart"
    assert wells[4].c.center.y - wells[0].c.center.y == 40 mm, "rows 40 apart"
    assert (wells[0].c.center.x + wells[11].c.center.x) / 2 == plate.center.x - 25 mm, "grid 25 left of centre"
    assert (wells[0].c.center.y + wells[11].c.center.y) / 2 == plate.center.y, "grid centred vertically"
    assert paw.bb.center_x - plate.center.x == 80 mm, "paw 80 right of centre"
    assert paw.pad.bb.width >= 29 mm and paw.pad.bb.width <= 31 mm, "pad about 30 wide"
    assert notch_left.c.radius == 10 mm, "R10 notches"
}
