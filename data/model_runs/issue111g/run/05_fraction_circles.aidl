# Fraction circles for a classroom, 3 mm plywood: four discs of 100 mm diameter, a whole one
# and one cut into 2 halves, one into 3 thirds, one into 4 quarters (10 pieces in all).
# The cuts start at the top (90 deg) and go round counter-clockwise.
# Each piece pushed out 1.5 mm from its disc's centre along its middle angle, so no two pieces
# share a cut line; the discs' centres on one row, 110 mm apart (whole, halves, thirds, quarters).
# Each piece engraved with its fraction in single strokes 8 mm high: "1" at the whole disc's
# centre, "1/2", "1/3", "1/4" centred 30 mm (60 % of the radius) from its disc's centre along
# the piece's middle angle.
units mm
thickness 3 mm

disc_r = 50 mm
pitch = 110 mm
push = 1.5 mm

def piece(n=2, k=0, x0=0 mm, y0=0 mm) -> solid {
    s = Sector(center=(x0 + push * cos(90 deg + (k + 0.5) * 360 deg / n),
                       y0 + push * sin(90 deg + (k + 0.5) * 360 deg / n)),
               radius=disc_r, start_angle=90 deg + k * 360 deg / n,
               end_angle=90 deg + (k + 1) * 360 deg / n)
    drawing label {
        t = Text(f"1/{n}", position=(x0 + 0.6 * disc_r * cos(90 deg + (k + 0.5) * 360 deg / n),
                                     y0 + 0.6 * disc_r * sin(90 deg + (k + 0.5) * 360 deg / n)),
                 size=8, valign="middle")
    }
}

assembly fractions {
    solid whole {
        disc = Circle(center=(0, 0), diameter=2 * disc_r)
        drawing label {
            t = Text("1", position=(0, 0), size=8, valign="middle")
        }
    }
    for k in range(2) {
        half = piece(n=2, k=k, x0=pitch, y0=0 mm)
    }
    for k in range(3) {
        third = piece(n=3, k=k, x0=2 * pitch, y0=0 mm)
    }
    for k in range(4) {
        quarter = piece(n=4, k=k, x0=3 * pitch, y0=0 mm)
    }

    # the request's numbers
    assert whole.disc.diameter == 100 mm, "100 mm discs"
    assert half[0].s.radius == 50 mm and quarter[3].s.radius == 50 mm, "100 mm discs"
    assert len(half) == 2 and len(third) == 3 and len(quarter) == 4, "2 + 3 + 4 pieces"
    assert len(half) + len(third) + len(quarter) + 1 == 10, "10 pieces in all"
    assert abs(distance(half[0].s.center, half[1].s.center) - 2 * 1.5 mm) < 0.001 mm, "pushed 1.5 mm"
    assert abs(half[0].s.center.x + 1.5 mm - 110 mm) < 0.001 mm, "first half pushed left"
    assert abs(whole.disc.center.x + 110 mm - (half[0].s.center.x + half[1].s.center.x) / 2) < 0.001 mm, "110 mm apart"
    assert abs((quarter[0].s.center.x + quarter[2].s.center.x) / 2 - 3 * 110 mm) < 0.001 mm, "quarters' disc 330 mm over"
    assert abs(distance(quarter[1].label.t.position, quarter[1].s.center) - (30 mm - 1.5 mm)) < 0.001 mm, "label 30 mm out"
}
