# Request: a birthday "explosion box" gift for Anna's 30th, laser-cut from 0.4 mm card
# (300 gsm). Three nested crosses, each a square base with four walls as tall as it is wide
# that fold up round it: outer 100 mm, middle 96 mm, inner 92 mm. Folds are scored
# (engraved lines along the base's edges). The outer walls each have a heart window (34 mm
# wide) in the middle, the heart upright when the wall stands. The middle walls each hold a
# 60 x 60 mm photo, centred, by four diagonal corner slits (12 mm in along each photo edge
# ... slit 2 mm past it). The inner walls each carry one word, engraved 12 mm bold, reading
# upright when the wall stands: HAPPY, 30TH, BIRTHDAY, ANNA. A lift-off lid: a 102 mm square
# top with 25 mm deep sides, glue tabs (12 mm, 45 degree ends) on the ends of the left and
# right sides, folds scored, and "30" cut through the top as a 40 mm bold stencil.

units mm
thickness 0.4 mm
min_wall 0.5 mm

param outer = 100 mm, min = 80, max = 120
step = 4 mm
lid_depth = 25 mm
# the four walls: direction of each from the base (right, top, left, bottom)
dirs = [0 deg, 90 deg, 180 deg, 270 deg]
words = ["HAPPY", "30TH", "BIRTHDAY", "ANNA"]
def rx(u, v, a) = u * cos(a) - v * sin(a)
def ry(u, v, a) = u * sin(a) + v * cos(a)

def heart(x=0 mm, y=0 mm, a=0 deg) -> hole {
    l = Hull(Circle(center=(x + rx(-8, 5, a), y + ry(-8, 5, a)), radius=9),
             Point(x + rx(0, -16, a), y + ry(0, -16, a)))
    r = Hull(Circle(center=(x + rx(8, 5, a), y + ry(8, 5, a)), radius=9),
             Point(x + rx(0, -16, a), y + ry(0, -16, a)))
}

def layer(s=100 mm, kind=0) -> solid {
    base = Rectangle(center=(0, 0), width=s, height=s)
    for k in range(4) {
        wall = Rectangle(center=(s * cos(dirs[k]), s * sin(dirs[k])), width=s, height=s)
    }
    drawing folds {
        f1 = Line((-s / 2, -s / 2), (s / 2, -s / 2))
        f2 = Line((s / 2, -s / 2), (s / 2, s / 2))
        f3 = Line((s / 2, s / 2), (-s / 2, s / 2))
        f4 = Line((-s / 2, s / 2), (-s / 2, -s / 2))
    }
    if kind == 0 {
        for k in range(4) {
            hw = heart(x=s * cos(dirs[k]), y=s * sin(dirs[k]), a=dirs[k] - 90 deg)
        }
    }
    if kind == 1 {
        cut slits {
            for k in range(4) {
                for c in [(1, 1), (-1, 1), (-1, -1), (1, -1)] {
                    sl = Line((s * cos(dirs[k]) + c[0] * 18 mm, s * sin(dirs[k]) + c[1] * 32 mm),
                              (s * cos(dirs[k]) + c[0] * 32 mm, s * sin(dirs[k]) + c[1] * 18 mm))
                }
            }
        }
    }
    if kind == 2 {
        drawing msg {
            for k in range(4) {
                w = Text(words[k], position=(s * cos(dirs[k]), s * sin(dirs[k])), size=12,
                         font="sans:Bold", valign="middle", rotation=dirs[k] - 90 deg,
                         fill=true)
            }
        }
    }
}

assembly gift {
    outer_box = layer(s=outer, kind=0)
    middle = layer(s=outer - step, kind=1)
    inner = layer(s=outer - 2 * step, kind=2)
    solid lid {
        top = Rectangle(center=(0, 0), width=outer + 2 mm, height=outer + 2 mm)
        for k in range(4) {
            side = Rectangle(center=((outer + 2 mm + lid_depth) / 2 * cos(dirs[k]),
                                     (outer + 2 mm + lid_depth) / 2 * sin(dirs[k])),
                             width=(lid_depth if k % 2 == 0 else outer + 2 mm),
                             height=(outer + 2 mm if k % 2 == 0 else lid_depth))
        }
        # glue tabs on the ends of the left and right sides
        for e in [(1, 1), (1, -1), (-1, 1), (-1, -1)] {
            tab = Trapezoid(center=(e[0] * (outer + 2 mm + lid_depth) / 2,
                                    e[1] * ((outer + 2 mm) / 2 + 6 mm)),
                            bottom_width=lid_depth, top_width=lid_depth - 24 mm, height=12,
                            rotation=(0 deg if e[1] > 0 else 180 deg))
        }
        hole number {
            n = Text("30", position=(0, 0), size=40, font="sans:Bold", valign="middle",
                     stencil=true)
        }
        drawing folds {
            g = Rectangle(center=(0, 0), width=outer + 2 mm, height=outer + 2 mm)
            for e in [(1, 1), (1, -1), (-1, 1), (-1, -1)] {
                t = Line((e[0] * (outer + 2 mm) / 2, e[1] * (outer + 2 mm) / 2),
                         (e[0] * ((outer + 2 mm) / 2 + lid_depth), e[1] * (outer + 2 mm) / 2))
            }
        }
    }
    RightOf(middle, outer_box, gap=10)
    AlignTop(middle, outer_box)
    Below(inner, outer_box, gap=10)
    AlignLeft(inner, outer_box)
    RightOf(lid, inner, gap=10)
    AlignTop(lid, inner)

    assert outer_box.base.bb.width == 100 mm, "outer 100"
    assert middle.base.bb.width == 96 mm and inner.base.bb.width == 92 mm, "96, 92"
    assert outer_box.wall[1].bb.height == 100 mm, "walls as tall as the base is wide"
    assert len(outer_box.hw) == 4, "four hearts"
    assert outer_box.hw[1].bb.width <= 34.5 mm and outer_box.hw[1].bb.width >= 33.5 mm,
        "heart 34 wide"
    assert len(middle.slits.sl) == 4 and len(middle.slits.sl[0]) == 4, "16 photo slits"
    assert len(inner.msg.w) == 4, "four words"
    assert lid.top.bb.width == 102 mm, "lid top 102"
    assert lid.side[1].bb.height == 25 mm, "lid 25 deep"
    assert lid.tab[0].height == 12 mm, "12 mm glue tabs"
}
