# Bathroom makeup-brush holder top: a 3 mm acrylic plate 120 x 80 mm, corners R5;
# a grid of 2 rows x 4 columns of 14 mm holes, 25 mm apart both ways, the grid centred
# left-right and its centre 8 mm above the plate's centre; "BRUSHES" in sans 7 mm
# (outline letters engraved), centred, baseline 10 mm above the bottom edge.
thickness 3 mm

param hole_d = 14 mm, min = 8 mm, max = 18 mm
param pitch = 25 mm, min = 20 mm, max = 28 mm

solid top {
    body = RoundedRectangle(center=(0, 0), width=120, height=80, corner_radius=5)

    hole cup {
        c = Circle(center=(0, 0), diameter=hole_d)
    }
    cups = GridPattern(cup, 2, 4, pitch)
    (cups[0].c.center.x + cups[7].c.center.x) / 2 == body.center.x
    (cups[0].c.center.y + cups[7].c.center.y) / 2 == body.center.y + 8 mm

    drawing label {
        t = Text("BRUSHES", (0, 0), size=7, font="sans")
    }
    AlignCenterX(label, body)
    label.t.position.y == body.bb.bottom + 10 mm

    assert body.bb.width == 120 mm and body.bb.height == 80 mm, "120 x 80"
    assert len(cups) == 8, "2 x 4 holes"
    assert cups[1].c.center.x - cups[0].c.center.x == 25 mm, "25 apart in x"
    assert cup.c.diameter == 14 mm, "14 mm holes"
    assert label.t.position.y - body.bb.bottom == 10 mm, "label 10 up"
}
