# A guitar body for a laser-cut ukulele kit: a closed spline outline through twelve
# points (an exact smooth curve in SVG, DXF and STEP), a round sound hole with an engraved
# rosette, a slot for the bridge and four engraved strings between them.
# Try: --set waist=22  --set lower_bout=48  --set hole_radius=14

units mm
param waist = 26, min = 10, max = 52, step = 1       # half width at the waist
param lower_bout = 44, min = 20, max = 88, step = 1  # half width of the lower bout
param upper_bout = 32, min = 18, max = 64, step = 1  # half width of the upper bout
# the rosette (5 mm wider than the hole) stays inside the body between the waist and the
# upper bout: its radius follows them (the bounds found on the spline's outline)
param hole_radius = 12, min = 4, step = 1, max = min(15, upper_bout - 5,
                                                     upper_bout / 2 + waist / 4 - 4, waist / 2 + 8)
thickness 3 mm

solid body {
    outline = Spline(points=[(0, -60), (0.86 * lower_bout, -52), (lower_bout, -20),
                             (waist, 2), (upper_bout, 30), (18, 52), (0, 56),
                             (-18, 52), (-upper_bout, 30), (-waist, 2),
                             (-lower_bout, -20), (-0.86 * lower_bout, -52)],
                     closed=true)
    hole sound {
        c = Circle(center=(0, 22), radius=hole_radius)
    }
    hole bridge {
        slot = Slot(center=(0, -30), length=34, width=4)
    }
    drawing rosette {
        inner = Circle(center=(0, 22), radius=hole_radius + 3)
        outer = Circle(center=(0, 22), radius=hole_radius + 5)
    }
    drawing strings {
        for i in range(4) {
            s = Line(start=(-6 + 4 * i, -26), end=(-6 + 4 * i, 16 - hole_radius))  # 1 mm short of the rosette
        }
    }
}
