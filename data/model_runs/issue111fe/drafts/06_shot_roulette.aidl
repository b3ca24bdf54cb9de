# Request (parties): a shot-glass roulette board for a birthday party, 6 mm ply.
# - base: a 420 mm disc with an M6 pivot hole in the centre; engraved in the middle: a
#   roulette wheel of 16 pockets 22.5 deg each: a pocket band from r 110 to r 125 with every
#   other pocket filled, spokes from r 35 to r 110 and the numbers 1-16 (10 mm bold) at r 90
#   reading outward.
# - glass ring: an annulus 420 outside, 270 inside, glued on the base, with 16 holes of
#   47 mm for shot glasses on a 345 mm pitch circle, each in line with its pocket.
# - spinner: an arrow on the M6 pivot (M6 clearance hole), a 28 mm hub, its point 105 mm
#   from the pivot (short of the pocket band, which it points at), a round tail (20 mm,
#   45 mm behind), "SPIN" engraved on it.
# - a 30 mm washer (M6 bore) between base and spinner so the spinner clears the ring's
#   level; the ring's inside (r 135) stays clear of the spinning arrow.

units mm
thickness 6 mm

import "std/fasteners.aidl"
import "std/shapes.aidl"

t = 6 mm
pockets = 16
step = 360 deg / pockets
pcd = 345 mm
glass_d = 47 mm

assembly roulette {
    solid base {
        disc = Circle(center=(0, 0), diameter=420)
        pivot = clearance_hole(size=6, cx=0, cy=0)
        # FIX after the first valid program: W0513 said each pocket's outline lay on its
        # neighbour's (the shared radial edges burnt twice). Now the 8 filled pockets are
        # Sectors and the 8 open ones only their two arcs, so no stroke is drawn twice.
        drawing wheel {
            inner = Circle(center=(0, 0), radius=35)
            for i in range(pockets // 2) {
                pocket = Sector(center=(0, 0), radius=125, inner_radius=110,
                                start_angle=2 * i * step, end_angle=(2 * i + 1) * step,
                                fill=true)
                rim = Arc(center=(0, 0), radius=125, start_angle=(2 * i + 1) * step,
                          end_angle=(2 * i + 2) * step)
                foot = Arc(center=(0, 0), radius=110, start_angle=(2 * i + 1) * step,
                           end_angle=(2 * i + 2) * step)
            }
            for i in range(pockets) {
                spoke = Line(polar((0, 0), 35, i * step), polar((0, 0), 110, i * step))
                num = Text(str(i + 1), position=polar((0, 0), 90, (i + 0.5) * step), size=10,
                           font="sans:Bold", valign="middle",
                           rotation=(i + 0.5) * step - 90 deg, fill=true)
            }
        }
    }

    solid ring {
        outer = Circle(center=(0, 0), diameter=420)
        hole middle {
            c = Circle(center=(0, 0), diameter=270)
        }
        hole glasses {
            for i in range(pockets) {
                g = Circle(center=polar((0, 0), pcd / 2, (i + 0.5) * step), diameter=glass_d)
            }
        }
    }

    solid spinner {
        arrow = Hull(Circle(center=(0, 0), radius=14), Point(105, 0))
        tail = Hull(Circle(center=(0, 0), radius=14), Circle(center=(-45, 0), radius=10))
        pivot = clearance_hole(size=6, cx=0, cy=0)
        drawing word {
            w = Text("SPIN", position=(52, 0), size=8, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }

    spacer = washer(outer=30 mm, inner=6.4 mm)

    # 3D: base, then the ring and the washer on it, the spinner on the washer
    Place(base, position=(0, 0, 0))
    Place(ring, position=(0, 0, t))
    Place(spacer, position=(0, 0, t))
    Place(spinner, position=(0, 0, 2 * t))

    # the sheet
    RightOf(ring, base, gap=8)
    AlignTop(ring, base)
    Below(spinner, base, gap=8)
    AlignLeft(spinner, base)
    RightOf(spacer, spinner, gap=8)
    AlignTop(spacer, spinner)

    # the request's numbers
    assert base.disc.diameter == 420 mm and ring.outer.diameter == 420 mm, "420 discs"
    assert ring.middle.c.diameter == 270 mm, "270 inside"
    assert len(ring.glasses.g) == 16 and len(base.wheel.num) == 16, "16 of each"
    assert len(base.wheel.pocket) == 8 and len(base.wheel.rim) == 8, "every other one filled"
    assert ring.glasses.g[0].diameter == 47 mm, "47 mm glass holes"
    assert distance(ring.glasses.g[0].center, (0, 0)) == 345 mm / 2, "345 pitch circle"
    assert distance(ring.glasses.g[0].center, ring.glasses.g[1].center) - glass_d >= 15 mm,
        "15 mm or more between glasses"
    assert pcd / 2 - glass_d / 2 - 270 mm / 2 >= 10 mm, "glass holes clear of the inside"
    assert 420 mm / 2 - pcd / 2 - glass_d / 2 >= 10 mm, "glass holes clear of the rim"
    assert spinner.arrow.bb.right == 105 mm, "arrow point 105 from the pivot"
    assert spinner.arrow.bb.right < 110 mm, "the point stops short of the pocket band"
    assert 270 mm / 2 - spinner.arrow.bb.right >= 25 mm, "the arrow clears the ring"
    assert spinner.tail.bb.left == -55 mm, "tail 20 mm round, 45 behind"
    assert base.pivot.c.diameter == spinner.pivot.c.diameter, "one M6 pivot"
    assert spacer.bb.width == 30 mm, "30 mm washer"
}
