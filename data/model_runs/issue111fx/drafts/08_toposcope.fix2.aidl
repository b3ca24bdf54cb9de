# Request: a toposcope (viewpoint indicator) for the summit of Beacon Hill, for our walking
# club, to bolt onto the cairn's slate top. Two layers:
# - Base, 6 mm exterior ply disc 300 mm across: in the middle "BEACON HILL" and "261 m"
#   engraved filled; six rays to landmarks, each a line from 40 mm out to an arrowhead whose
#   tip is 124 mm out, at its compass bearing (clockwise from north), labelled along the ray
#   with its name and distance, always readable (never upside down):
#   Castle Ridge 12 km at 35 deg, Lake Verran 8 km at 110, St Anne's Spire 5 km at 160,
#   Harbour 14 km at 215, Pike Fell 21 km at 280, Wind Farm 9 km at 330.
# - Bezel, 3 mm black acrylic ring 300 / 250 on top: N, E, S, W cut through it (14 mm letters,
#   the base shows through), engraved ticks every 10 degrees (3 mm, 5 mm at every 30) except
#   at the four letters.
# Four 5 mm screw holes 140 mm out at 45, 135, 225, 315 degrees through both, countersunk
# 10 mm in the bezel.
# FIX after the first valid program: two labels ran into their arrowheads (W0513: "12 km"
# into Castle Ridge's, "5 km" into St Anne's Spire's). The labels now end 8 mm short of the
# arrowheads' base: centred 76 mm out, at most 64 mm long.
# FIX 2: max_width gave the six labels five different sizes (3.57 to 4.5 mm, notes W0113);
# one size for all, 3.5 mm, which fits the longest in 64 mm.

units mm
import "std/shapes.aidl"

def ang(b) = 90 deg - b * 1 deg                   # compass bearing -> drawing angle
def readable(b) = ang(b) if cos(ang(b)) >= 0 else ang(b) + 180 deg

landmarks = [["CASTLE RIDGE", 12, 35], ["LAKE VERRAN", 8, 110], ["ST ANNE'S SPIRE", 5, 160],
             ["HARBOUR", 14, 215], ["PIKE FELL", 21, 280], ["WIND FARM", 9, 330]]

assembly toposcope {
    solid base {
        thickness 6 mm
        disc = Circle(center=(0, 0), diameter=300)
        screws = bolt_circle(count=4, pcd=280, hole_d=5, start=45 deg)
        drawing middle {
            name = Text("BEACON HILL", position=(0, 3), size=6, font="sans:Bold", fill=true)
            height = Text("261 m", position=(0, -8), size=5, font="sans:Bold", fill=true)
        }
        drawing rays {
            for lm in landmarks {
                ray = Line(polar((0, 0), 40, ang(lm[2])), polar((0, 0), 116, ang(lm[2])))
                tip = Polygon([polar((0, 0), 124, ang(lm[2])),
                               polar((0, 0), 116, ang(lm[2]) + 2.5 deg),
                               polar((0, 0), 116, ang(lm[2]) - 2.5 deg)], fill=true)
                label = Text(f"{lm[0]}  {lm[1]} km",
                             position=polar((0, 0), 76, ang(lm[2])) +
                                      polar((0, 0), 5, readable(lm[2]) + 90 deg),
                             size=3.5, rotation=readable(lm[2]), valign="middle")
            }
        }
    }

    solid bezel {
        thickness 3 mm
        ring = Circle(center=(0, 0), diameter=300)
        hole opening { c = Circle(center=(0, 0), diameter=250) }
        screws = bolt_circle(count=4, pcd=280, hole_d=5, start=45 deg)
        Countersink(screws, diameter=10)
        hole letters {
            n = Text("N", position=polar((0, 0), 137.5, ang(0)), size=14, font="sans:Bold",
                     valign="middle")
            e = Text("E", position=polar((0, 0), 137.5, ang(90)), size=14, font="sans:Bold",
                     valign="middle")
            s = Text("S", position=polar((0, 0), 137.5, ang(180)), size=14, font="sans:Bold",
                     valign="middle")
            w = Text("W", position=polar((0, 0), 137.5, ang(270)), size=14, font="sans:Bold",
                     valign="middle")
        }
        drawing ticks {
            for b in range(0, 360, 10) {
                if b % 90 != 0 {
                    tk = Line(polar((0, 0), 126, ang(b)),
                              polar((0, 0), 126 + (5 if b % 30 == 0 else 3), ang(b)))
                }
            }
        }
    }

    RightOf(bezel, base, gap=10)
    AlignCenterY(bezel, base)
    Place(base, position=(0, 0, 0))
    Place(bezel, on=base, position=(0, 0))

    # the request's numbers
    assert base.disc.diameter == 300 mm and bezel.ring.diameter == 300 mm, "300 mm"
    assert bezel.opening.c.diameter == 250 mm, "bezel ring 300 / 250"
    assert len(base.rays.ray) == 6 and len(base.rays.label) == 6, "six landmarks"
    assert abs(distance(base.rays.tip[0].points[0], base.disc.center) - 124 mm) < 0.01 mm,
        "arrow tips 124 mm out"
    assert 124 mm + 0.5 mm <= 250 mm / 2, "the tips show inside the bezel"
    assert distance(base.middle, base.rays) >= 2 mm, "the name clear of the rays"
    assert base.middle.bb.width <= 2 * 40 mm - 6 mm, "the name inside the rays' start"
    assert distance(base.rays.label[0], base.rays.label[1]) >= 2 mm and
        distance(base.rays.label[1], base.rays.label[2]) >= 2 mm and
        distance(base.rays.label[3], base.rays.label[4]) >= 2 mm and
        distance(base.rays.label[4], base.rays.label[5]) >= 2 mm and
        distance(base.rays.label[5], base.rays.label[0]) >= 2 mm, "labels apart"
    assert distance(base.rays.label[0], base.rays.ray[0]) >= 1 mm, "label beside its ray"
    assert distance(base.rays.label[0], base.rays.tip) >= 2 mm and
        distance(base.rays.label[2], base.rays.tip) >= 2 mm, "labels clear of the arrowheads"
    assert len(bezel.ticks.tk) == 32, "36 ticks less the four letters"
    assert distance(bezel.letters, bezel.ticks) >= 1 mm, "ticks clear of the letters"
    assert distance(bezel.letters, bezel.screws) >= 3 mm, "letters clear of the screws"
    assert distance(bezel.letters, bezel.opening) >= 2 mm, "letters inside the ring"
    assert abs(distance(bezel.screws.bolt[0].center, bezel.ring.center) - 140 mm) < 0.01 mm,
        "screws 140 out"
}
