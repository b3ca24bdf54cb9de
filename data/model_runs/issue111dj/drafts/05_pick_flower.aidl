# Request: a guitar-pick holder for a mic stand, 3 mm cast acrylic, laser kerf 0.15 mm.
# A disc 90 mm across with a 16.3 mm centre hole: it goes over the stand's 5/8"-27 thread
# and is clamped under the mic clip. Nine radial slits, 40 degrees apart, each cut 16 mm in
# from the rim, hold picks standing up by friction: three widths for three pick gauges,
# 0.5, 0.7 and 0.9 mm, repeating round the disc (first slit on +x). Each slit's width
# engraved (".5", ".7", ".9", 3.5 mm letters) on a circle of radius 22, in line with its
# slit, upright.

thickness 3 mm
kerf 0.15 mm

R = 45 mm
depth = 16 mm
widths = [0.5 mm, 0.7 mm, 0.9 mm]
names = [".5", ".7", ".9"]

solid pick_flower {
    disc = Circle(center=(0, 0), diameter=2 * R)
    hole thread {
        c = Circle(center=(0, 0), diameter=16.3)
    }
    hole slits {
        for i in range(9) {
            # from R - depth out to 1 mm past the rim, so it opens cleanly
            s = Rectangle(center=polar((0, 0), R - depth / 2 + 0.5 mm, i * 40 deg),
                          width=depth + 1 mm, height=widths[i % 3], rotation=i * 40 deg)
        }
    }
    drawing labels {
        ring = Circle(center=(0, 0), radius=22, construction=true)
        for i in range(9) {
            t = Text(names[i % 3], along=ring, angle=i * 40 deg, size=3.5)
        }
    }

    # the request's numbers
    assert disc.diameter == 90 mm, "disc 90 across"
    assert thread.c.diameter == 16.3 mm, "5/8 in thread hole"
    assert len(slits.s) == 9, "nine slits"
    assert slits.s[1].height == 0.7 mm and slits.s[5].height == 0.9 mm and
        slits.s[6].height == 0.5 mm, "gauges repeat .5 .7 .9"
    assert R - (slits.s[0].center.x - (depth + 1 mm) / 2) == 16 mm, "slits 16 deep"
}
