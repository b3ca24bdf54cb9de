# Request (music): a bullroarer (the ancient spinning aerophone) from 6 mm hardwood ply.
# A lens-shaped slat 300 mm long (tip to tip, tips rounded to 8 mm) and 60 mm wide at the
# middle; 10 semicircular notches 5 mm across along each edge between x = -110 and 110 mm
# (they make it roar louder); a 6 mm cord hole on the centre line 15 mm from one tip.
# Engraved: "BULLROARER" (10 mm letters) along the middle, and a zig-zag "lightning" line
# on each side of it.

units mm
thickness 6 mm

chord = 329 mm      # the lens's chord before its tips are rounded
sag = 30 mm         # half its width
R = (square(chord / 2) + square(sag)) / (2 * sag)
def ytop(x) = sqrt(square(R) - square(x)) - (R - sag)
tip_angle = 2 * asin(chord / 2 / R)
tip_round = 8 mm
rounded_tip_x = chord / 2 - (tip_round / sin(tip_angle / 2) - tip_round)

solid roarer {
    lens = Intersect(Circle(center=(0, sag - R), radius=R), Circle(center=(0, R - sag), radius=R))
    Fillet(at=(-chord / 2, 0), radius=tip_round)
    Fillet(at=(chord / 2, 0), radius=tip_round)

    hole notches {
        for i in range(10) {
            a = Circle(center=(-110 + i * 220 / 9, ytop(-110 + i * 220 / 9)), diameter=5)
            b = Circle(center=(-110 + i * 220 / 9, -ytop(-110 + i * 220 / 9)), diameter=5)
        }
    }
    hole cord { c = Circle(center=(-rounded_tip_x + 15, 0), diameter=6) }

    drawing art {
        word = Text("BULLROARER", position=(0, 0), size=10, valign="middle")
        zig_top = Polyline([(-60, 13), (-45, 19), (-30, 13), (-15, 19), (0, 13), (15, 19),
                            (30, 13), (45, 19), (60, 13)])
        zig_bottom = Polyline([(-60, -13), (-45, -19), (-30, -13), (-15, -19), (0, -13),
                               (15, -19), (30, -13), (45, -19), (60, -13)])
    }

    assert abs(2 * rounded_tip_x - 300 mm) < 1 mm, "300 mm long tip to tip"
    assert lens.bb.height == 60 mm, "60 mm wide"
    assert len(notches.a) == 10 and len(notches.b) == 10, "10 notches each edge"
    assert notches.a[9].center.x - notches.a[0].center.x == 220 mm, "notches from -110 to 110"
    assert cord.c.center.x - (-rounded_tip_x) == 15 mm, "cord hole 15 mm from the tip"
}
