# Camping: a campfire pot trammel (adjustable pot hanger) cut from 3 mm steel
# on a fibre laser. A bar 240 mm long (vertical) x 30 mm wide with 4 mm corner
# radius. A 12 mm hole for the tripod's cord centred 12 mm below the top; a
# 10 mm hole for an S-hook centred 12 mm above the bottom. Seven saw-tooth
# notches in the right edge for the pot's bail: each a horizontal ledge 12 mm
# deep, its slanted side returning to the edge 10 mm higher (the bail rests on
# the ledge and cannot slide out); the first ledge 40
# mm below the top, the others 22 mm apart downward. "POT HANGER" engraved 5 mm
# tall along the bar, reading bottom to top, 7 mm left of the centre line,
# centred on the bar's middle.

units mm
thickness 3 mm

notches = 7
step = 22 mm
depth = 12 mm
drop = 10 mm

solid trammel {
    bar = RoundedRectangle(center=(0, 0), width=30, height=240, corner_radius=4)

    hole cord {
        c = Circle(center=(0, 120 - 12), diameter=12)
    }
    hole hook {
        c = Circle(center=(0, -120 + 12), diameter=10)
    }
    hole teeth {
        for i in range(notches) {
            # FIX after the first valid program: the ledge is the notch's floor (the bail
            # rests on it), the slant above it; the first valid program had the ledge as the
            # notch's ceiling, so a bail pulled down slid out along the slant.
            # the cut runs 1 mm past the edge along the slant's line, so it opens cleanly
            n = Polygon([(16, 80 - i * step), (15 - depth, 80 - i * step),
                         (16, 80 - i * step + drop * (depth + 1) / depth)])
        }
    }
    drawing label {
        t = Text("POT HANGER", position=(-7, 0), size=5, valign="middle", rotation=90 deg)
    }

    assert bar.width == 30 mm and bar.height == 240 mm, "bar 240 x 30"
    assert bar.bb.top - cord.c.center.y == 12 mm and cord.c.diameter == 12 mm, "cord hole 12, 12 below the top"
    assert hook.c.center.y - bar.bb.bottom == 12 mm and hook.c.diameter == 10 mm, "hook hole 10, 12 above the bottom"
    assert len(teeth.n) == 7, "seven notches"
    assert bar.bb.top - teeth.n[0].points[0].y == 40 mm, "first ledge 40 below the top"
    assert teeth.n[0].points[0].y - teeth.n[1].points[0].y == 22 mm, "ledges 22 apart"
    assert bar.bb.right - teeth.n[0].points[1].x == 12 mm, "ledges 12 deep"
}
