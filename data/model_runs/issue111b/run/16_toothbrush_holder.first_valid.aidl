# Toothbrush holder top plate, 4 mm acrylic: a regular hexagon 100 mm across flats (flats at top
# and bottom) with its corners rounded R5; a 28 mm hole in the center for a toothpaste tube;
# four 14 mm holes for brushes on a 34 mm radius circle, at 45, 135, 225 and 315 deg; a 3 mm
# peg hole near each of the six corners, 9 mm in from the corner toward the center (for the
# legs). "BRUSH" engraved 5 mm tall centered between the center hole and the bottom flat.

units mm
thickness 4 mm

param af = 100 mm, min = 80 mm, max = 150 mm

solid holder {
    hex = RegularPolygon(center=(0, 0), across_flats=af, sides=6)
    Fillet(hex, 5)

    hole tube {
        c = Circle(center=(0, 0), diameter=28)
    }

    hole brush {
        c = Circle(center=(0, 0), diameter=14)
    }
    Coincident(brush.c.center, polar(hex.center, 34, 45 deg))
    brushes = CircularPattern(brush, 4, hex.center)

    hole peg {
        c = Circle(center=(0, 0), diameter=3)
    }
    Coincident(peg.c.center, polar(hex.center, af / sqrt(3) - 9 mm, 0 deg))
    pegs = CircularPattern(peg, 6, hex.center)

    drawing label {
        t = Text("BRUSH", position=(0, -(14 + af / 2) / 2), size=5, valign="middle")
    }

    assert abs(hex.bb.height - 100 mm) < 0.01 mm, "100 mm across flats"
    assert tube.c.diameter == 28 mm, "28 mm tube hole"
    assert len(brushes) == 4 and brush.c.diameter == 14 mm, "four 14 mm brush holes"
    assert abs(distance(brushes[1].c.center, hex.center) - 34 mm) < 0.001 mm, "on a 34 mm radius"
    assert abs(brushes[0].c.center.x - brushes[0].c.center.y) < 0.001 mm and brushes[0].c.center.x > 0 mm, "first at 45 deg"
    assert len(pegs) == 6, "six peg holes"
    assert abs(distance(pegs[0].c.center, hex.points[0]) - 9 mm) < 0.001 mm, "peg 9 mm in from the corner"
    assert abs(label.t.size - 5 mm) < 0.001 mm, "5 mm label"
}
