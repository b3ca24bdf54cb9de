# Science: an optics-bench lens holder upright, 5 mm black acrylic, 80 mm wide x 110 mm tall,
# top corners R10, bottom corners square. A 38 mm lens opening whose centre (the optical axis)
# is 70 mm above the bottom edge, centred across; three 3 mm holes for a retaining ring on a
# 46 mm circle round it, 120 deg apart, the first straight above the centre. Two 3.4 mm
# screw holes countersunk 6.5 mm, 15 mm above the bottom edge and 20 mm in from each side.
# Engraved: a 6 mm axis-height tick on each side edge at 70 mm, and "LENS f=100" 5 mm
# centred 30 mm above the bottom edge.

thickness 5 mm

solid holder {
    body = RoundedRectangle(center=(0, 0), width=80, height=110, corner_radii=[10, 10, 0, 0])

    hole lens { c = Circle(center=(0, 15), diameter=38) }
    At(lens.c.center, body.bottom.midpoint, dy=70)

    hole ring_screw { c = Circle(center=(0, 38), diameter=3) }
    At(ring_screw.c.center, lens.c.center, dy=23)
    ring = CircularPattern(ring_screw, 3, lens.c.center)

    hole screw { c = Circle(center=(-20, -40), diameter=3.4) }
    At(screw.c.center, body.bottom_left, dx=20, dy=15)
    axis = Line((0, -60), (0, 60), construction=true)
    Vertical(axis)
    Midpoint(body.center, axis)
    screw2 = Mirrored(screw, about=axis)
    Countersink([screw, screw2], diameter=6.5)

    drawing marks {
        left_tick = Line((-40, 15), (-34, 15))
        right_tick = Line((34, 15), (40, 15))
        label = Text("LENS f=100", (0, -25), size=5, valign="middle")
    }
    Coincident(marks.left_tick.start, polar(lens.c.center, 40, 180 deg))
    Horizontal(marks.left_tick)
    Length(marks.left_tick, 6)
    Coincident(marks.right_tick.end, polar(lens.c.center, 40, 0 deg))
    Horizontal(marks.right_tick)
    Length(marks.right_tick, 6)
    At(marks.label.position, body.bottom.midpoint, dy=30)

    assert body.bb.width == 80 mm and body.bb.height == 110 mm, "80 x 110"
    assert lens.c.diameter == 38 mm, "lens 38"
    assert lens.c.center.y - body.bb.bottom == 70 mm, "axis 70 high"
    assert len(ring) == 3, "three ring screws"
    assert distance(ring[1].c.center, lens.c.center) == 23 mm, "on a 46 circle"
    assert screw.c.center.y - body.bb.bottom == 15 mm, "screws 15 up"
    assert screw.c.center.x - body.bb.left == 20 mm, "screw 20 in"
    assert body.bb.right - screw2.c.center.x == 20 mm, "screw 20 in (right)"
    assert marks.left_tick.start.x == body.bb.left, "tick on the edge"
}
