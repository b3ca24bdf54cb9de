# Request: a pair of limbo stands for a garden party, from 12 mm plywood, cut on a
# 1300 x 900 mm bed. Each stand is an upright 1200 mm tall: a post 120 mm wide that
# flares at the bottom to a base 360 mm wide over its lowest 250 mm (the inside corners
# rounded R40, the top corners R10), and a foot 400 mm long and 100 mm tall crossing it
# at the bottom, cross-halved (a 50 mm slot up the upright's middle, a 50 mm slot down
# the foot's middle). The bar is a broom handle that rests on two 10 mm dowel pegs: each
# upright has eight 10.5 mm peg holes on its centre line, the lowest 400 mm above the
# floor, then every 100 mm up to 1100 mm; each hole's height in cm (40 ... 110) is
# engraved filled in 14 mm bold figures to its right. Two stands: four parts.

import "std/joints.aidl"

units mm
t = 12 mm
thickness t
kerf 0.2 mm

pegs_n = 8
low_peg = 400 mm
peg_step = 100 mm

def limbo_stand() -> assembly {
    solid upright {
        outline = Polygon([(-180, 0), (180, 0), (60, 250), (60, 1200), (-60, 1200), (-60, 250)])
        Fillet([outline.points[2], outline.points[5]], 40)
        Fillet([outline.points[3], outline.points[4]], 10)
        notch = cross_halving(depth=50 mm, thickness=t, rotation=180 deg, cx=0 mm, cy=0 mm)
        hole peg {
            c = Circle(center=(0, low_peg), diameter=10.5)
        }
        pegs = LinearPattern(peg, pegs_n, (0, peg_step))
        drawing heights {
            for i in range(pegs_n) {
                label = Text(str(40 + 10 * i), position=(16, low_peg + i * peg_step), size=14,
                             anchor="start", valign="middle", font="sans:Bold", fill=true)
            }
        }
        Fixed(outline)
    }
    solid foot {
        bar = RoundedRectangle(bottom_left=(-200, 0), width=400, height=100,
                               corner_radii=[10, 10, 0, 0])
        notch = cross_halving(depth=50 mm, thickness=t, cx=0 mm, cy=100 mm)
    }
    RightOf(foot, upright, gap=10)
    AlignBottom(foot, upright)
    # 3D: the upright faces the front, the foot crosses it under its centre line
    Place(upright, position=(0, 0, 0), face="front", up="up")
    Place(foot, position=(-t / 2, -t / 2, 0), face="right", up="up")
}

assembly limbo {
    left = limbo_stand()
    right = limbo_stand()
    Below(right, left, gap=10)
    AlignLeft(right, left)

    assert left.upright.outline.bb.height == 1200 mm, "uprights 1200 mm tall"
    assert left.upright.outline.bb.width == 360 mm, "base 360 mm wide"
    assert len(left.upright.pegs) == 8, "eight peg holes"
    assert left.upright.pegs[0].c.diameter == 10.5 mm, "10.5 mm peg holes"
    assert left.upright.pegs[0].c.center.y - left.upright.outline.bb.bottom == 400 mm,
        "lowest peg 400 mm up"
    assert left.upright.pegs[7].c.center.y - left.upright.outline.bb.bottom == 1100 mm,
        "highest peg 1100 mm up"
    assert left.upright.pegs[1].c.center.y - left.upright.pegs[0].c.center.y == 100 mm,
        "pegs every 100 mm"
    assert left.foot.bar.width == 400 mm and left.foot.bar.height == 100 mm, "foot 400 x 100"
    assert left.upright.notch.depth + left.foot.notch.depth == 100 mm,
        "the halvings add up to the foot's height"
    assert len(left.upright.heights.label) == 8, "a height by every hole"
    assert distance(left.upright.heights, left.upright.pegs) >= 3 mm, "figures clear of the holes"
    assert left.upright.heights.bb.right <= left.upright.outline.bb.center_x + 60 mm - 5 mm,
        "figures on the post"
    assert left.upright.bb.height <= 1300 mm and left.upright.bb.width <= 900 mm, "fits the bed"

    Place(left, position=(0, 0, 0))
    Place(right, position=(1400, 0, 0))
}
