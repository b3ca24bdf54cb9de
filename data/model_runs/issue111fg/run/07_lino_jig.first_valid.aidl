# Request: a registration jig for printing a 150 x 100 mm lino block on A5 paper (210 x 148,
# landscape) with even margins (30 mm left and right, 24 mm top and bottom), from 6 mm MDF
# in three glued layers. Base: 300 x 240 mm. Window layer: the same size, with a window
# 152 x 102 mm (1 mm play round the block) whose centre is 15 mm right of and 15 mm below
# the board's centre, and a 30 mm half-round finger notch in the window's right edge to lift
# the block out. Paper fence: an L, arms 15 mm wide, glued on the window layer so that paper
# pushed into its corner has the block's image centred on it; its vertical arm runs from
# 20 mm below the paper's bottom edge, its horizontal arm to 10 mm past the paper's right
# edge. 6 mm pin holes through all the layers that meet there for gluing them square: 4 in
# the corners of base and window layer (15 mm in), 2 through the fence, the window layer
# and the base. Engraved on the window layer: "A5 LANDSCAPE  150 x 100 BLOCK" (6 mm single
# stroke) and an L mark at the paper's bottom-right corner (arms 10 mm).

units mm
thickness 6 mm

W = 300 mm
H = 240 mm
blk_w = 150 mm
blk_h = 100 mm
pap_w = 210 mm
pap_h = 148 mm
win_x = 15 mm
win_y = -15 mm
# the paper's corner (top-left) from the block's top-left
pap_left = win_x - (blk_w + 2 mm) / 2 + 1 mm - (pap_w - blk_w) / 2
pap_top = win_y + (blk_h + 2 mm) / 2 - 1 mm + (pap_h - blk_h) / 2
pins = [(-97.5, pap_top - pap_h + 20 mm), (40, pap_top + 7.5 mm)]

assembly jig {
    solid base {
        board = Rectangle(center=(0, 0), width=W, height=H)
        hole corner_pins {
            for p in [(-1, -1), (1, -1), (1, 1), (-1, 1)] {
                c = Circle(center=(p[0] * (W / 2 - 15 mm), p[1] * (H / 2 - 15 mm)), diameter=6)
            }
        }
        hole fence_pins {
            for q in pins { c = Circle(center=q, diameter=6) }
        }
    }
    solid window_layer {
        board = Rectangle(center=(0, 0), width=W, height=H)
        hole window {
            w = Rectangle(center=(win_x, win_y), width=blk_w + 2 mm, height=blk_h + 2 mm)
            notch = Circle(center=(win_x + (blk_w + 2 mm) / 2, win_y), diameter=30)
        }
        hole corner_pins {
            for p in [(-1, -1), (1, -1), (1, 1), (-1, 1)] {
                c = Circle(center=(p[0] * (W / 2 - 15 mm), p[1] * (H / 2 - 15 mm)), diameter=6)
            }
        }
        hole fence_pins {
            for q in pins { c = Circle(center=q, diameter=6) }
        }
        drawing marks {
            label = Text("A5 LANDSCAPE  150 x 100 BLOCK", position=(win_x, -H / 2 + 14 mm),
                         size=6)
            corner_x = Line((pap_left + pap_w, pap_top - pap_h),
                            (pap_left + pap_w - 10 mm, pap_top - pap_h))
            corner_y = Line((pap_left + pap_w, pap_top - pap_h),
                            (pap_left + pap_w, pap_top - pap_h + 10 mm))
        }
    }
    solid fence {
        l = Polygon([(pap_left - 15 mm, pap_top - pap_h - 20 mm),
                     (pap_left, pap_top - pap_h - 20 mm),
                     (pap_left, pap_top),
                     (pap_left + pap_w + 10 mm, pap_top),
                     (pap_left + pap_w + 10 mm, pap_top + 15 mm),
                     (pap_left - 15 mm, pap_top + 15 mm)])
        hole fence_pins {
            for q in pins { c = Circle(center=q, diameter=6) }
        }
    }
    RightOf(window_layer, base, gap=15)
    AlignBottom(window_layer, base)
    RightOf(fence, window_layer, gap=15)
    AlignBottom(fence, window_layer)

    Place(base, position=(0, 0, 0))
    Place(window_layer, position=(0, 0, 6))
    Place(fence, position=(0, 0, 12))

    assert base.board.bb.width == 300 mm and base.board.bb.height == 240 mm, "300 x 240"
    assert window_layer.window.w.bb.width == 152 mm and window_layer.window.w.bb.height == 102 mm,
        "window 152 x 102"
    assert window_layer.window.w.center.x - window_layer.board.center.x == 15 mm, "15 right"
    assert window_layer.window.w.center.y - window_layer.board.center.y == -15 mm, "15 down"
    # the block sits 1 mm in from the window's top-left; the paper's corner is the fence's
    assert (window_layer.window.w.bb.left + 1 mm) - pap_left == 30 mm, "30 mm side margin"
    assert pap_top - (window_layer.window.w.bb.top - 1 mm) == 24 mm, "24 mm top margin"
    assert (pap_left + 210 mm) - (window_layer.window.w.bb.right - 1 mm) == 30 mm, "right margin"
    assert (window_layer.window.w.bb.bottom + 1 mm) - (pap_top - 148 mm) == 24 mm, "bottom margin"
    assert window_layer.window.notch.diameter == 30 mm, "30 mm notch"
    assert len(base.corner_pins.c) == 4 and len(fence.fence_pins.c) == 2, "4 + 2 pins"
    assert base.board.bb.right - base.corner_pins.c[1].center.x == 15 mm, "pins 15 in"
}
