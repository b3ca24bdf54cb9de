# Request: a set of Penrose kite-and-dart tiles for our school maths club, 3 mm birch ply.
# Long edges 60 mm, short edges 60 / phi (37.08 mm). Kite: 72 degrees at its tip between the
# long edges, 144 at the wide end between the short edges. Dart: 72 at its tip between the
# long edges, a 216 degree notch between the short edges. Conway's matching arcs engraved,
# each centred on a vertex so that it meets the edges square:
#   kite: a 1.2 mm filled band of radius 37.08 (the short edge) about its tip, and a thin line
#         of radius 22.92 (short / phi) about its wide end;
#   dart: a 1.2 mm filled band of radius 22.92 about its tip, and a thin line of radius 14.16
#         (short / phi^2) about its notch.
# Bands meet bands and lines meet lines only where the tiles are joined legally.
# Eight kites and five darts.

thickness 3 mm

phi = (1 + sqrt(5)) / 2
L = 60 mm
S = L / phi
sx = L * sin(36 deg)
sy = L * cos(36 deg)

def kite() -> solid {
    outline = Polygon([(0, 0), (sx, sy), (0, L), (-sx, sy)])
    drawing marks {
        band = Stroke(Arc(center=(0, 0), radius=S, start_angle=54 deg, end_angle=126 deg), width=1.2, cap="flat", fill=true)
        line = Arc(center=(0, L), radius=S / phi, start_angle=198 deg, end_angle=342 deg)
    }
}

def dart() -> solid {
    outline = Polygon([(0, 0), (sx, sy), (0, S), (-sx, sy)])
    drawing marks {
        band = Stroke(Arc(center=(0, 0), radius=S / phi, start_angle=54 deg, end_angle=126 deg), width=1.2, cap="flat", fill=true)
        line = Arc(center=(0, S), radius=S / phi / phi, start_angle=162 deg, end_angle=18 deg)
    }
}

assembly penrose_set {
    for i in range(8) {
        k = kite()
        k.outline.points[0] == ((i % 4) * 80 mm, -(i // 4) * 70 mm)
    }
    for j in range(5) {
        d = dart()
        d.outline.points[0] == (j * 80 mm, -150 mm)
    }

    assert len(k) == 8 and len(d) == 5, "eight kites, five darts"
    assert abs(distance(k[0].outline.points[0], k[0].outline.points[1]) - 60 mm) < 0.001 mm, "kite long edge 60"
    assert abs(distance(k[0].outline.points[1], k[0].outline.points[2]) - 37.08 mm) < 0.01 mm, "kite short edge 37.08"
    assert abs(distance(d[0].outline.points[0], d[0].outline.points[1]) - 60 mm) < 0.001 mm, "dart long edge 60"
    assert abs(distance(d[0].outline.points[1], d[0].outline.points[2]) - 37.08 mm) < 0.01 mm, "dart short edge 37.08"
    # the tip angle, 72 degrees: the two long edges' far ends are 2 x 60 x sin 36 apart
    assert abs(distance(k[0].outline.points[1], k[0].outline.points[3]) - 2 * 60 mm * sin(36 deg)) < 0.001 mm, "kite tip 72"
    assert abs(k[0].marks.line.radius - 22.92 mm) < 0.01 mm and abs(d[0].marks.line.radius - 14.16 mm) < 0.01 mm, "thin arcs"
    assert abs(d[0].marks.band.bb.height) > 0 mm, "dart band drawn"
}
