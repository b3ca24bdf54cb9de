# Request (holidays): a St Patrick's Day table centrepiece in 6 mm ply (painted green).
# A shamrock of three heart-shaped leaves meeting at a centre: each leaf is two lobes
# of 24 mm radius, their centres 45 mm out from the shamrock's centre and 22 deg either
# side of the leaf's axis, the leaves' axes at 90, 210 and 330 deg, each leaf's point
# at the centre. An 8 mm stem curves down from the centre to a 150 x 46 mm plaque
# (8 mm rounded corners) with SLÁINTE cut through it in 20 mm bold serif stencil
# letters, centred, 4 mm above the plaque's middle. The shamrock's centre is 100 mm
# above the plaque's middle. It stands on a trapezoid foot (110 mm at the bottom,
# 70 mm at the top, 24 mm tall) that crosses the plaque at its centre: a cross
# halving, 14 mm down from the foot's top, 10 mm up from the plaque's bottom.

import "std/joints.aidl"

thickness 6 mm

lobe_r = 24 mm
lobe_out = 45 mm
spread = 22
cy = 100 mm
plaque_w = 150 mm
plaque_h = 46 mm
foot_h = 24 mm

assembly centrepiece {
    solid front {
        for k in range(3) {
            la = Hull(Circle(center=(lobe_out * cos((90 + 120 * k - spread) * 1 deg),
                                     cy + lobe_out * sin((90 + 120 * k - spread) * 1 deg)),
                             radius=lobe_r), Point(0, cy))
            lb = Hull(Circle(center=(lobe_out * cos((90 + 120 * k + spread) * 1 deg),
                                     cy + lobe_out * sin((90 + 120 * k + spread) * 1 deg)),
                             radius=lobe_r), Point(0, cy))
        }
        stem = Stroke(Arc(start=(0, cy), through=(-10, 55), end=(0, 15)), width=8 mm)
        plaque = RoundedRectangle(center=(0, 0), width=plaque_w, height=plaque_h, corner_radius=8 mm)
        hole word {
            t = Text("SLÁINTE", position=(0, 4), size=20 mm, font="serif:Bold", stencil=true,
                     valign="middle")
        }
        h = cross_halving(depth=10 mm, thickness=6 mm, rotation=180 deg, cx=0 mm,
                          cy=-plaque_h / 2)
        Fixed(plaque)
    }

    solid foot {
        body = Trapezoid(center=(0, 0), bottom_width=110, top_width=70, height=foot_h)
        h = cross_halving(depth=14 mm, thickness=6 mm, cx=0 mm, cy=foot_h / 2)
    }
    RightOf(foot, front, gap=10 mm)
    AlignBottom(foot, front)

    assert front.h.depth + foot.h.depth == foot_h, "the halvings meet"
    assert len(front.la) == 3, "three leaves"
    assert front.plaque.bb.width == 150 mm and front.plaque.bb.height == 46 mm, "150 x 46 plaque"
    assert front.word.bb.width <= plaque_w - 2 * 10 mm, "letters 10 mm in from the ends"
    assert front.word.bb.bottom - front.h.bb.top >= 4 mm, "the halving slot clears the letters"
    assert front.word.bb.top <= front.plaque.bb.top - 3 mm, "letters inside the plaque"
    assert front.bb.height <= 200 mm, "under 200 mm tall"
}
