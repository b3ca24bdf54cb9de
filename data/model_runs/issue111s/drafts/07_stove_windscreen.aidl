# Camping: a folding stove windscreen of four identical panels, 1 mm aluminium, joined by
# split rings. Each panel 100 mm wide x 120 mm tall, top corners R6. A row of six 10 mm air
# holes 15 mm apart, centred, their centres 15 mm above the bottom edge. Along the left and
# right edges three 4 mm ring holes each, 5 mm in from the edge, at 20, 60 and 100 mm up.
# The four panels laid in a row 5 mm apart for cutting.

thickness 1 mm
param panel_w = 100 mm, min = 80 mm, max = 140 mm
param panel_h = 120 mm, min = 90 mm, max = 160 mm

def panel() -> solid {
    body = RoundedRectangle(center=(0, 0), width=panel_w, height=panel_h,
                            corner_radii=[6, 6, 0, 0])
    axis = Line((0, -70), (0, 70), construction=true)
    hole air {
        c = Circle(center=(-37.5, -45), diameter=10)
    }
    airs = LinearPattern(air, 6, (15, 0))
    air.c.center.x == body.center.x - 2.5 * 15 mm
    air.c.center.y == body.bb.bottom + 15

    hole ring {
        c = Circle(center=(-45, -40), diameter=4)
    }
    rings = LinearPattern(ring, 3, (0, 40))
    ring.c.center.x == body.bb.left + 5
    ring.c.center.y == body.bb.bottom + 20
    other_rings = Mirrored(rings, axis)
}

assembly windscreen {
    p1 = panel()
    p2 = panel()
    p3 = panel()
    p4 = panel()
    RightOf(p2, p1, gap=5)
    RightOf(p3, p2, gap=5)
    RightOf(p4, p3, gap=5)
    AlignBottom(p2, p1)
    AlignBottom(p3, p1)
    AlignBottom(p4, p1)

    assert p1.body.bb.width == 100 mm and p1.body.bb.height == 120 mm, "panel 100 x 120"
    assert len(p1.airs) == 6, "six air holes"
    assert p1.airs[1].c.center.x - p1.airs[0].c.center.x == 15 mm, "15 apart"
    assert abs((p1.airs[0].c.center.x + p1.airs[5].c.center.x) / 2 - p1.body.center.x) < 0.001, "row centred"
    assert p1.air.c.center.y - p1.body.bb.bottom == 15 mm, "air holes 15 up"
    assert p1.air.c.diameter == 10 mm, "10 mm air holes"
    assert len(p1.rings) == 3 and len(p1.other_rings) == 3, "three ring holes each side"
    assert p1.rings[2].c.center.y - p1.body.bb.bottom == 100 mm, "top ring 100 up"
    assert p1.body.bb.right - p1.other_rings[0].c.center.x == 5 mm, "right rings 5 in"
}
