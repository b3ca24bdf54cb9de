# Request: a four-decade resistance box for my electronics bench (x1k, x100, x10, x1 ohm
# switches, read left to right like the digits of 0 - 9999 ohm). A closed
# finger-jointed box of 3 mm ply, 260 x 100 x 70 mm outside, 10 mm fingers; its lid is the
# front panel. On the panel (centre as origin): four 9.5 mm rotary-switch holes on a line
# 5 mm above the centre, 50 mm apart, the first 95 mm left of the centre; each with a 3.2 mm
# anti-rotation key hole 7.5 mm straight above it. Round each switch an engraved dial: ten
# ticks (13 to 16 mm out) for positions 0 to 9, 30 deg apart, 0 at 225 deg (lower left),
# 9 at -45 deg (lower right), numbered at 20 mm (3.5 mm digits). Under each dial, at 35 mm
# below its centre, its factor "×1k", "×100", "×10", "×1" (5 mm, filled font). Two 6.5 mm
# binding-post holes 19 mm apart, 110 mm right of the centre (at y 14 and -5), "HI" above
# and "LO" below them. Title "DECADE BOX 0 – 9 999 Ω" along the top, 6 mm, filled font.

import "std/joints.aidl"

t = 3 mm
thickness t

factors = ["×1k", "×100", "×10", "×1"]
def ang(k) = 225 deg - k * 30 deg
def dial_x(i) = -95 + 50 * i

assembly decade_box {
    box = finger_box(length=260 mm, depth=100 mm, height=70 mm, thickness=t, finger=10 mm)

    hole panel_holes {
        for i in range(4) {
            sw = Circle(center=(dial_x(i), 5), diameter=9.5)
            key = Circle(center=(dial_x(i), 12.5), diameter=3.2)
        }
        post_hi = Circle(center=(110, 14), diameter=6.5)
        post_lo = Circle(center=(110, -5), diameter=6.5)
    }
    At(panel_holes.sw[0].center, box.lid.bb.center, dx=-95, dy=5)
    CutInto(panel_holes, box.lid)

    drawing panel_marks {
        ref = Point(-95, 5, construction=true)
        for i in range(4) {
            for k in range(10) {
                tick = Line((dial_x(i) + 13 * cos(ang(k)), 5 + 13 * sin(ang(k))), 3, ang(k))
                num = Text(str(k), position=(dial_x(i) + 20 * cos(ang(k)), 5 + 20 * sin(ang(k))),
                           size=3.5, valign="middle")
            }
            factor = Text(factors[i], position=(dial_x(i), 5 - 35), size=5, font="sans",
                          valign="middle", fill=true)
        }
        hi = Text("HI", position=(110, 24), size=5)
        lo = Text("LO", position=(110, -17), size=5)
        title = Text("DECADE BOX 0 – 9 999 Ω", position=(0, 37), size=6, font="sans",
                     fill=true)
    }
    At(panel_marks.ref, panel_holes.sw[0].center)
    CutInto(panel_marks, box.lid)

    # the request's numbers
    assert len(panel_holes.sw) == 4 and len(panel_holes.key) == 4, "four switches, four keys"
    assert abs(panel_holes.sw[0].diameter - 9.5 mm) < 0.01 mm, "9.5 mm switch holes"
    assert abs(panel_holes.sw[1].center.x - panel_holes.sw[0].center.x - 50 mm) < 0.01 mm, "switches 50 mm apart"
    assert abs(panel_holes.sw[3].center.x - panel_holes.sw[0].center.x - 150 mm) < 0.01 mm, "four switches over 150 mm"
    assert abs(panel_holes.key[2].center.y - panel_holes.sw[2].center.y - 7.5 mm) < 0.01 mm, "key 7.5 mm above"
    assert abs(panel_holes.sw[0].center.x - box.lid.bb.center_x + 95 mm) < 0.01 mm, "first switch 95 mm left of centre"
    assert abs(panel_holes.post_hi.center.y - panel_holes.post_lo.center.y - 19 mm) < 0.01 mm, "posts 19 mm apart"
    assert abs(panel_holes.post_hi.center.x - box.lid.bb.center_x - 110 mm) < 0.01 mm, "posts 110 mm right"
    assert len(panel_marks.tick) == 4 and len(panel_marks.tick[0]) == 10, "ten ticks per dial"
    assert abs(box.lid.bb.width - 260 mm) < 0.01 mm and abs(box.lid.bb.height - 100 mm) < 0.01 mm, "panel 260 x 100"
    assert panel_marks.title.bb.top <= box.lid.bb.top - 6 mm, "title clear of the back fingers"
    assert panel_marks.factor[0].bb.bottom >= box.lid.bb.bottom + 6 mm, "factors clear of the front fingers"
}
