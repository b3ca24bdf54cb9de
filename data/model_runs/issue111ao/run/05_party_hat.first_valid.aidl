# Request (parties): a flat blank for a cone party hat, cut from 0.4 mm (300 gsm)
# card. Rolled up, the hat is 150 mm across the base: the blank is a sector of
# radius 200 mm (the slant height) spanning 135 degrees, apex at the top. A
# 12 mm glue tab along the right-hand straight edge, from 20 mm below the apex
# to the rim, its ends cut back at 45 degrees, with an engraved score line where
# it folds. Two 3 mm holes for the chin elastic, 12 mm in from the rim, placed
# so that they face each other across the rolled hat. Five 5-point star
# cut-outs (16 mm across the tips) on an arc of radius 110 mm, 22 degrees apart,
# each pointing at the apex. "HAPPY BIRTHDAY" engraved along the rim, 12 mm
# letters, baseline 20 mm in from the rim, readable from below.

import "std/plates.aidl"

thickness 0.4 mm

slant = 200 mm
spread = 135 deg
tab_w = 12 mm
a0 = 270 deg - spread / 2    # left straight edge
a1 = 270 deg + spread / 2    # right straight edge (the glue tab's)
ux = cos(a1)
uy = sin(a1)
nx = cos(a1 + 90 deg)        # outward, away from the sector
ny = sin(a1 + 90 deg)

solid hat {
    blank = Sector(center=(0, 0), radius=slant, start_angle=a0, end_angle=a1)

    # glue tab: 20 mm from the apex to the rim, 12 mm wide, ends cut at 45 degrees
    tab = Polygon([(20 mm * ux, 20 mm * uy),
                   (slant * ux, slant * uy),
                   ((slant - tab_w) * ux + tab_w * nx, (slant - tab_w) * uy + tab_w * ny),
                   ((20 mm + tab_w) * ux + tab_w * nx, (20 mm + tab_w) * uy + tab_w * ny)])

    hole elastic {
        for k in range(2) {
            c = Circle(center=((slant - 12 mm) * cos(270 deg + (2 * k - 1) * spread / 4),
                               (slant - 12 mm) * sin(270 deg + (2 * k - 1) * spread / 4)),
                       diameter=3 mm)
        }
    }

    hole stars {
        for i in range(5) {
            s = Star(center=(110 mm * cos(270 deg + (i - 2) * 22 deg),
                             110 mm * sin(270 deg + (i - 2) * 22 deg)),
                     points=5, outer_radius=8 mm, inner_radius=3.5 mm,
                     rotation=(i - 2) * 22 deg)
        }
    }

    drawing score {
        fold = Line((20 mm * ux, 20 mm * uy), (slant * ux, slant * uy))
    }

    drawing greeting {
        guide = Circle(center=(0, 0), radius=slant - 20 mm, construction=true)
        words = Text("HAPPY BIRTHDAY", along=guide, angle=270 deg, flip=true, size=12 mm)
    }
    Concentric(greeting.guide, blank)

    assert blank.radius == 200 mm, "slant height 200 mm"
    assert 2 * pi * 75 mm - slant * (spread / 1 rad) < 0.01 mm and
        2 * pi * 75 mm - slant * (spread / 1 rad) > -0.01 mm, "rolls to 150 mm across"
    assert len(elastic.c) == 2 and elastic.c[0].diameter == 3 mm, "two 3 mm elastic holes"
    assert distance(elastic.c[0].center, blank.center) == 188 mm, "elastic 12 mm in from the rim"
    assert len(stars.s) == 5, "five stars"
    assert stars.s[0].outer_radius == 8 mm, "stars 16 mm across the tips"
    assert distance(stars.s[2].center, blank.center) == 110 mm, "stars on a 110 mm arc"
}
