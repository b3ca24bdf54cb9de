# Request (crafts): a calligrapher's ink and dip-pen stand, three layers of 6 mm walnut ply
# glued into one 18 mm block, 200 x 100 mm with R10 corners. On the left a 51 mm well,
# 12 mm deep (through the top two layers), holds a 50 mm ink bottle, centred 60 mm left of
# the middle and 10 mm behind it, with a 9 mm radius finger notch on its left side to lift
# the bottle out. In front of the well a 50 x 14 mm nib tray (R4), 6 mm deep (top layer
# only), centred under the well and 36 mm in front of the middle. Two upright pen cradles,
# 70 mm long and 30 mm above the top, at x = 0 and x = 85 mm, each with three 10 mm U-notches
# 10 mm deep at y = -20, 0, 20 so three pens lie across both; each cradle stands on two
# 15 mm tenons, 22 mm either side of its middle, through the top two layers (0.15 mm over)
# onto the base layer. "M. Calloway" engraved (filled, serif italic, 8 mm) centred at
# x = 42 mm, 40 mm in front of the middle.

units mm
t = 6 mm
thickness t

L = 200 mm
D = 100 mm
well_x = -60 mm
well_y = 10 mm
well_d = 51 mm
tray_y = -36 mm
cradle_xs = [0 mm, 85 mm]
notch_ys = [-20 mm, 0 mm, 20 mm]
ten_y = 22 mm
fit = 0.15 mm
rest_h = 30 mm

def layer(well=true, tray=false, mortises=true) -> solid {
    body = RoundedRectangle(center=(0, 0), width=L, height=D, corner_radius=10)
    if well {
        hole bottle {
            c = Circle(center=(well_x, well_y), diameter=well_d)
            lift = Circle(center=(well_x - well_d / 2, well_y), radius=9)
        }
    }
    if tray {
        hole nibs {
            r = RoundedRectangle(center=(well_x, tray_y), width=50, height=14, corner_radius=4)
        }
    }
    if mortises {
        hole slots {
            for i in range(2) {
                for k in range(2) {
                    m = Rectangle(center=(cradle_xs[i], (2 * k - 1) * ten_y), width=t + fit,
                                  height=15 + fit)
                }
            }
        }
    }
}

def cradle() -> solid {
    # x runs front to back (world y), y = 0 on the top layer's face
    body = Rectangle(bottom_left=(-35, 0), width=70, height=rest_h)
    ten_f = Rectangle(center=(-ten_y, -t), width=15, height=2 * t)
    ten_b = Rectangle(center=(ten_y, -t), width=15, height=2 * t)
    hole notches {
        for k in range(3) {
            u = Circle(center=(notch_ys[k], rest_h - 5 mm), radius=5)
            mouth = Rectangle(bottom_left=(notch_ys[k] - 5 mm, rest_h - 5 mm), width=10,
                              height=5 mm + 1 mm)
        }
    }
}

assembly ink_stand {
    base = layer(well=false, tray=false, mortises=false)
    middle = layer(well=true, tray=false, mortises=true)
    top = layer(well=true, tray=true, mortises=true)
    drawing owner {
        n = Text("M. Calloway", position=(42 mm, -40 mm), size=8, font="serif:Italic",
                 valign="middle", fill=true)
    }
    CutInto(owner, top)
    cradle_l = cradle()
    cradle_r = cradle()

    # flat on the sheet
    Below(middle, base, gap=8)
    AlignLeft(middle, base)
    Below(top, middle, gap=8)
    AlignLeft(top, middle)
    RightOf(cradle_l, base, gap=8)
    AlignTop(cradle_l, base)
    Below(cradle_r, cradle_l, gap=8)
    AlignLeft(cradle_r, cradle_l)
    At(owner.n.position, top.body.center, dx=42 mm, dy=-40 mm)

    # assembled: the three layers stacked, cradles standing on the base layer
    Place(base, position=(0, 0, 0), face="up")
    Place(middle, position=(0, 0, t), face="up")
    Place(top, position=(0, 0, 2 * t), face="up")
    Place(cradle_l, position=(cradle_xs[0] - t / 2, 0, 3 * t), face="right", up="up")
    Place(cradle_r, position=(cradle_xs[1] - t / 2, 0, 3 * t), face="right", up="up")

    assert top.body.width == 200 mm and top.body.height == 100 mm, "200 x 100 block"
    assert top.bottle.c.diameter == 51 mm and middle.bottle.c.diameter == 51 mm,
        "51 mm well through the top two layers (12 deep)"
    assert top.nibs.r.width == 50 mm and top.nibs.r.height == 14 mm, "nib tray 50 x 14"
    assert distance(top.nibs.r, top.bottle.c) >= 5 mm, "tray clear of the well"
    assert distance(owner, top.nibs) >= 5 mm, "name clear of the tray"
    assert owner.bb.bottom >= top.body.bb.bottom + 2 mm, "name on the block"
    assert len(cradle_l.notches.u) == 3, "three pens"
    assert cradle_l.body.height == 30 mm, "cradles 30 mm above the top"
    assert cradle_xs[1] - cradle_xs[0] == 85 mm, "cradles 85 apart"
    assert abs(cradle_xs[1]) + t / 2 <= L / 2 - 10 mm, "right cradle clear of the end"
}
