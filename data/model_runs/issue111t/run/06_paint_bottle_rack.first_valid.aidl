# Crafts: craft-paint bottle rack top, 6 mm plywood. A 300 x 90 mm plate, corners R6. Two rows
# of seven 32 mm bottle holes at 40 mm pitch both ways, the grid centred on the plate. A 4 mm
# screw hole 8 mm in from each corner (both ways), countersunk 8 mm.
thickness 6 mm

solid rack {
    body = RoundedRectangle(center=(0, 0), width=300, height=90, corner_radius=6)
    hole bottle {
        c = Circle(center=(-120, -20), diameter=32)
    }
    bottles = GridPattern(bottle, rows=2, cols=7, spacing=40 mm)
    hole screw {
        c = Circle(center=(-142, -37), diameter=4)
    }
    screws = CornerPattern(screw, body, inset=8 mm)
    Countersink(screws, diameter=8 mm)

    assert body.bb.width == 300 mm and body.bb.height == 90 mm, "300 x 90"
    assert len(bottles) == 14, "2 x 7 bottles"
    assert bottles[1].c.center.x - bottles[0].c.center.x == 40 mm, "40 pitch across"
    assert bottles[7].c.center.y - bottles[0].c.center.y == 40 mm, "40 pitch up"
    assert abs((bottles[0].c.center.x + bottles[13].c.center.x) / 2 - body.center.x) < 0.01 mm, "centred across"
    assert abs((bottles[0].c.center.y + bottles[13].c.center.y) / 2 - body.center.y) < 0.01 mm, "centred up"
    assert len(screws) == 4, "four screws"
    assert screws[0].c.center.x - body.bb.left == 8 mm and screws[0].c.center.y - body.bb.bottom == 8 mm, "8 in"
}
