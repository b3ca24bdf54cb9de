# Camping: a hammock spreader bar from 6 mm birch plywood, 420 mm long overall.
# The bar's long edges are shallow arcs: 45 mm wide in the middle, 30 mm wide where they meet
# the round ends (R15, centred 195 mm either side of the middle). An 8 mm hole for the line
# at each end's centre. Four lightening slots 50 x 12 mm along the axis, centred 75 and
# 135 mm either side of the middle. "TRAIL REST" engraved in the middle, sans outlines
# (not filled), 9 mm tall, centred on the axis.

units mm
thickness 6 mm

param half = 195 mm, min = 150 mm, max = 240 mm

solid spreader {
    top = Arc(start=(-half, 15), through=(0, 22.5), end=(half, 15))
    right_side = Line((half, 15), (half, -15))
    bottom = Arc(start=(half, -15), through=(0, -22.5), end=(-half, -15))
    left_side = Line((-half, -15), (-half, 15))
    left_end = Circle(center=(-half, 0), radius=15)
    right_end = Circle(center=(half, 0), radius=15)

    hole lines {
        a = Circle(center=(-half, 0), diameter=8)
        b = Circle(center=(half, 0), diameter=8)
    }

    hole lighten {
        for x in [-135, -75, 75, 135] {
            s = Slot(center=(x, 0), length=50, width=12)
        }
    }

    drawing name {
        t = Text("TRAIL REST", position=(0, 0), size=9, font="sans", valign="middle")
    }

    assert self.bb.width == 420 mm, "420 mm overall"
    assert top.through.y - bottom.through.y == 45 mm, "45 mm wide in the middle"
    assert top.start.y - bottom.end.y == 30 mm, "30 mm at the ends"
    assert lines.b.center.x - lines.a.center.x == 2 * 195 mm, "line holes 195 either side"
    assert len(lighten.s) == 4, "four slots"
    assert lighten.s[2].center.x == 75 mm and lighten.s[3].center.x == 135 mm, "slots at 75, 135"
    assert name.t.size == 9 mm, "9 mm letters"
}
