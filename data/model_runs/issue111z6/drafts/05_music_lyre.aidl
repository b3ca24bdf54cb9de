# Music: a marching-band lyre (flip-folder holder) for a saxophone, cut from 3 mm acrylic.
# The frame is one 6 mm band with round ends along a path: a U-shaped arc from (-30, 30)
# through (0, 8) to (30, 30), and from each end an arm curving out through (+-38, 55),
# in through (+-30, 80) and out to a tip at (+-36, 100). A 6 mm crossbar centred 80 mm up,
# 60 mm long, joins the arms; three 2.5 mm "strings" at x = -10, 0, 10 run from the U
# up into the crossbar. Below the U a stem 8 mm wide reaches 55 mm below the frame's
# lowest point, with a 3 mm hole 6 mm from its end for the lyre clamp's screw;
# "ALTO" engraved 4 mm high along the stem.

thickness 3 mm

param band = 6 mm, min = 4 mm, max = 8 mm
param string_w = 2.5 mm, min = 2 mm, max = 4 mm

solid lyre {
    # FIX after the first valid program: the arc and the two arm splines met at (+-30, 30)
    # with different tangents, a visible kink in the band; one spline through the same
    # points is smooth.
    path = Spline([(-36, 100), (-30, 80), (-38, 55), (-30, 30), (0, 8), (30, 30),
                   (38, 55), (30, 80), (36, 100)], construction=true)
    frame = Stroke(path, width=band)
    # the windows between frame, crossbar and strings are the lyre's (W0515)
    AllowOverlap(frame, bar, string)

    bar = Rectangle(center=(0, 80), width=60, height=band)

    for x in [-10, 0, 10] {
        string = Rectangle(bottom_left=(x - string_w / 2, 10.5), width=string_w, height=80 - 10.5)
    }

    stem = Rectangle(bottom_left=(-4, 5 - 55), width=8, height=60)
    hole clamp {
        c = Circle(center=(0, 5 - 55 + 6), diameter=3)
    }

    drawing label {
        t = Text("ALTO", position=(0, -22), size=4, rotation=90, valign="middle")
    }

    assert abs(frame.bb.bottom - 5 mm) < 0.01 mm, "frame's lowest point 3 mm below the arc's"
    assert abs(frame.bb.bottom - stem.bb.bottom - 55 mm) < 0.01 mm, "stem 55 mm below the frame"
    assert stem.width == 8 mm, "stem 8 mm wide"
    assert clamp.c.center.y - stem.bb.bottom == 6 mm and clamp.c.diameter == 3 mm, "3 mm hole 6 mm from the end"
    assert len(string) == 3, "three strings"
    assert bar.width == 60 mm and bar.center.y == 80 mm, "crossbar 60 mm, 80 mm up"
}
