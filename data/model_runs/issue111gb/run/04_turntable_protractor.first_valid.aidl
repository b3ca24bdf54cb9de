# Request (music, hi-fi): a two-point cartridge alignment protractor for a turntable,
# Baerwald alignment for the IEC groove radii (inner 60.325 mm, outer 146.05 mm): null
# points 66.04 mm and 120.89 mm from the spindle centre. 2 mm clear acrylic, kerf 0.1 mm.
# - Outline: a paddle, the hull of a 44 mm disc round the spindle and a 50 mm disc centred
#   150 mm out. Spindle hole 7.30 mm (for a 7.24 mm spindle).
# - Engraved: a radial line from 8 mm to 170 mm out from the spindle centre; at each null
#   point a 0.8 mm filled dot and a grid: 5 lines across the radial line, 2 mm apart and
#   24 mm long, centred on the null point, crossed by 5 lines along it, 6 mm apart, as long
#   as the grid is deep (8 mm); each null's radius in 3.5 mm figures ("66.04", "120.89")
#   centred over its grid, the baseline 3 mm beyond the grid's end;
# - the inner and outer groove radii as arcs about the spindle, the inner from -18 to 18 deg,
#   the outer from -9 to 9 deg;
# - "BAERWALD  IEC" in 4 mm letters between the two grids, its baseline 10 mm under the radial line.

units mm
thickness 2 mm
kerf 0.1 mm

nulls = [66.04 mm, 120.89 mm]

solid protractor {
    near = Circle(center=(0, 0), diameter=44, construction=true)
    far = Circle(center=(150, 0), diameter=50, construction=true)
    paddle = Hull(near, far)
    hole spindle { c = Circle(center=(0, 0), diameter=7.30) }

    drawing marks {
        radial = Line((8, 0), (170, 0))
        for n in nulls {
            dot = Circle(center=(n, 0), diameter=0.8, fill=true)
            for k in range(5) {
                across = Line((n - 4 mm + k * 2 mm, -12), (n - 4 mm + k * 2 mm, 12))
            }
            for k in [0, 1, 3, 4] {   # the middle line along is the radial line itself
                along = Line((n - 4 mm, -12 + k * 6), (n + 4 mm, -12 + k * 6))
            }
            figure = Text(f"{n / 1 mm:.2f}", position=(n, 15), size=3.5)
        }
        inner_groove = Arc(center=(0, 0), radius=60.325, start_angle=-18 deg, end_angle=18 deg)
        outer_groove = Arc(center=(0, 0), radius=146.05, start_angle=-9 deg, end_angle=9 deg)
        title = Text("BAERWALD  IEC", position=(93.5, -10), size=4, max_width=42.5 mm)
    }

    # the request's numbers
    assert near.diameter == 44 mm and far.diameter == 50 mm, "paddle discs 44 and 50"
    assert far.center.x - near.center.x == 150 mm, "far disc 150 out"
    assert spindle.c.diameter == 7.30 mm, "spindle hole 7.30"
    assert abs(distance(marks.dot[0].center, spindle.c.center) - 66.04 mm) < 0.001 mm, "inner null 66.04"
    assert abs(distance(marks.dot[1].center, spindle.c.center) - 120.89 mm) < 0.001 mm, "outer null 120.89"
    assert len(marks.across[0]) == 5 and len(marks.along[1]) + 1 == 5, "5 by 5 grid lines (the radial line is the middle one along)"
    assert marks.across[0][1].start.x - marks.across[0][0].start.x == 2 mm, "across lines 2 apart"
    assert marks.across[1][0].length == 24 mm, "across lines 24 long"
    assert marks.along[0][1].start.y - marks.along[0][0].start.y == 6 mm, "along lines 6 apart"
    assert marks.figure[0].position.y - marks.across[0][0].end.y == 3 mm, "figures 3 beyond the grid"
    assert marks.inner_groove.radius == 60.325 mm and marks.outer_groove.radius == 146.05 mm, "IEC groove radii"
    assert marks.radial.start.x - spindle.c.center.x == 8 mm and marks.radial.end.x - spindle.c.center.x == 170 mm, "radial 8 to 170"
    assert marks.radial.end.x < paddle.bb.right - 2 mm, "radial line ends on the paddle"
    assert distance(marks.title, marks.across) >= 2 mm, "title clear of the grids"
    assert distance(marks.figure[0], marks.inner_groove) >= 1 mm, "66.04 clear of the inner groove arc"
    assert marks.radial.start.y - marks.title.position.y == 10 mm, "title 10 under the radial line"
}
