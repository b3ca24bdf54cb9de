# Parties: a flat-pack cupcake stand of 3 mm plywood. Two uprights, each a trapezoid
# 120 mm wide at the foot, 60 mm at the top and 160 mm tall, with a 40 x 3 mm tab on
# top; they cross-halve (0.2 mm clearance): one slotted from the top, one from the
# bottom, each slot half of the 163 mm overall height. Each upright has two 20 mm
# round cut-outs, 30 mm either side of its centre line, 40 mm above the foot.
# A 200 mm round tier rests on the uprights' shoulders; the crossed tabs go through a
# plus-shaped opening in its centre (two 40.2 x 3.2 mm slots crossing at right angles).
# "HAPPY BIRTHDAY" engraved 8 mm high on the tier, 60 mm below its centre.
import "std/joints.aidl"
thickness 3 mm

param clearance = 0.2 mm, min = 0 mm, max = 0.4 mm

def upright(from_top=true) -> solid {
    body = Trapezoid(center=(0, 80), bottom_width=120, top_width=60, height=160)
    tab = Rectangle(center=(0, 161.5), width=40, height=3)
    if from_top {
        h = cross_halving(depth=81.5 mm, thickness=3 mm, clearance=clearance, cx=0 mm, cy=163 mm)
    } else {
        h = cross_halving(depth=81.5 mm, thickness=3 mm, clearance=clearance, rotation=180 deg,
                          cx=0 mm, cy=0 mm)
    }
    hole window {
        c = Circle(center=(-30, 40), diameter=20)
    }
    windows = LinearPattern(window, 2, (60, 0))
}

assembly stand {
    a = upright(from_top=true)
    b = upright(from_top=false)
    RightOf(b, a, gap=10)
    AlignBottom(b, a)

    solid tier {
        disc = Circle(center=(300, 80), diameter=200)
        hole plus {
            h1 = Rectangle(center=(300, 80), width=40 + clearance, height=3 + clearance)
            h2 = Rectangle(center=(300, 80), width=3 + clearance, height=40 + clearance)
        }
        Concentric(plus.h1, disc)
        Concentric(plus.h2, disc)
        drawing words { t = Text("HAPPY BIRTHDAY", (300, 20), size=8, valign="middle") }
        AlignCenterX(words, disc)
        words.t.position.y == disc.center.y - 60 mm
    }
    RightOf(tier, b, gap=10)

    assert a.body.height + a.tab.height == 163 mm, "163 overall"
    assert a.body.bottom_width == 120 mm and a.body.top_width == 60 mm, "foot 120, top 60"
    assert a.h.depth + b.h.depth == 163 mm, "slots meet"
    assert tier.disc.diameter == 200 mm, "tier 200"
    assert a.windows[1].c.center.x - a.windows[0].c.center.x == 60 mm, "cut-outs 30 either side"
}
