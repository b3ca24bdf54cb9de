# Request (garden): a grow-through plant support ring for a peony clump, cut
# from 6 mm exterior plywood. A round rim 250 mm outside diameter and 12 mm
# wide; inside it a square grid of 6 mm bars on a 50 mm pitch both ways (five
# bars each way, the middle ones on the centre lines) that the stems grow up
# through; three round lugs on the outside of the rim, at 90, 210 and 330
# degrees, each with a 10 mm hole for a bamboo cane (hole centre 132 mm from the
# ring's centre, 7 mm of wood round it). All corners where bars meet the rim or
# each other rounded R3 so they do not snag the stems.

thickness 6 mm

outer_d = 250 mm
rim_w = 12 mm
bar_w = 6 mm
pitch = 50 mm
bars = 5
cane_d = 10 mm
lug_r = 132 mm

solid ring {
    inner = Circle(center=(0, 0), diameter=outer_d - 2 * rim_w, construction=true)
    rim = Shell(inner, rim_w)

    # the grid: each bar clipped to a circle between the rim's inner and outer edge
    for i in range(bars) {
        v = Intersect(Rectangle(center=((i - (bars - 1) / 2) * pitch, 0), width=bar_w,
                                height=outer_d),
                      Circle(center=(0, 0), diameter=outer_d - rim_w))
        h = Intersect(Rectangle(center=(0, (i - (bars - 1) / 2) * pitch), width=outer_d,
                                height=bar_w),
                      Circle(center=(0, 0), diameter=outer_d - rim_w))
    }

    # three lugs with cane holes
    for k in range(3) {
        lug = Circle(center=polar(inner.center, lug_r, 90 deg + k * 120 deg),
                     radius=cane_d / 2 + 7 mm)
        hole cane {
            c = Circle(center=polar(inner.center, lug_r, 90 deg + k * 120 deg), diameter=cane_d)
        }
    }

    Fillet(3 mm)

    assert rim.bb.width == 250 mm, "rim 250 mm outside diameter"
    assert (rim.bb.width - inner.diameter) / 2 == 12 mm, "rim 12 mm wide"
    assert len(v) == 5 and len(h) == 5, "five bars each way"
    assert len(cane) == 3, "three cane holes"
    assert cane[0].c.diameter == 10 mm, "10 mm cane holes"
    assert distance(cane[1].c.center, inner.center) == 132 mm, "cane hole 132 mm out"
    assert lug[0].radius - cane[0].c.radius == 7 mm, "7 mm of wood round the cane"
}
