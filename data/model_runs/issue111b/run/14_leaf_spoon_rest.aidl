# Leaf-shaped spoon rest, 6 mm plywood: a leaf blade 120 mm long (base at x = -60, pointed tip at
# x = +60 mm) and about 70 mm wide at its widest (a smooth outline through (-50, +-22),
# (-20, +-35), (20, +-30), (45, +-15)), sharp at the tip, plus a stem 8 mm wide with a round end
# running 20 mm left from the blade's base (140 mm overall). Engraved: a midrib from the base to
# 8 mm short of the tip, and four pairs of side veins leaving the midrib at x = -35, -10, 15,
# 35 mm and running 15 mm forward to 18, 20, 16 and 8 mm either side of the midrib.

units mm
thickness 6 mm

solid leaf {
    blade = Spline([(-60, 0), (-50, -22), (-20, -35), (20, -30), (45, -15), (60, 0),
                    (45, 15), (20, 30), (-20, 35), (-50, 22)], closed=true, corners=[5])
    stem = Slot(start=(-76, 0), end=(-58, 0), width=8)

    drawing veins {
        midrib = Line((-60, 0), (52, 0))
        xs = [-35, -10, 15, 35]
        hs = [18, 20, 16, 8]
        for i in range(4) {
            up = Line((xs[i], 0), (xs[i] + 15, hs[i]))
            down = Line((xs[i], 0), (xs[i] + 15, -hs[i]))
        }
    }

    assert abs(self.bb.width - 140 mm) < 0.5 mm, "140 mm overall"
    assert abs(blade.bb.height - 70 mm) < 3 mm, "about 70 mm wide"
    assert abs(blade.bb.right - veins.midrib.end.x - 8 mm) < 0.001 mm, "midrib stops 8 mm short of the tip"
    assert len(veins.up) == 4 and len(veins.down) == 4, "four pairs of veins"
    assert abs(blade.bb.left - stem.bb.left - 20 mm) < 0.001 mm, "stem runs 20 mm left of the base"
}
