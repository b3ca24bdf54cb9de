# A 15 cm ruler: a long bar with a hanging hole, millimetre ticks along the
# top edge with centimetre numbers, and an inch scale (1/8" ticks) along the
# bottom edge. Ticks and numbers are drawings (engraved, not cut).
# Try: --set length_cm=30  --set width=40

param length_cm = 15
param width = 36 mm
margin = 8 mm  # blank bar before the zero mark
tail = 22 mm   # blank bar after the last mark (holds the hole)
scale_len = length_cm * 10 mm
inches = floor(scale_len / 25.4 mm * 8)  # number of 1/8 inch steps that fit

solid ruler {
    bar = RoundedRectangle(center=((margin + scale_len + tail) / 2, width / 2),
                           width=margin + scale_len + tail, height=width, corner_radius=2)

    hole hang {
        eye = Circle(center=(margin + scale_len + tail / 2, width / 2), diameter=7)
    }

    # metric scale: 1 mm ticks hanging from the top edge, longer every 5 and 10
    drawing metric {
        for i in range(length_cm * 10 + 1) {
            h = 10 if i % 10 == 0 else (7 if i % 5 == 0 else 4)
            tick = Line((margin + i * 1 mm, width), (margin + i * 1 mm, width - h))
        }
        for cm in range(length_cm + 1) {
            label = Text(str(cm), (margin + cm * 10 mm, width - 16), size=4)
        }
        unit = Text("cm", (margin + scale_len + tail / 2, width - 9), size=3)
    }

    # imperial scale: 1/8 inch ticks rising from the bottom edge
    drawing imperial {
        for i in range(inches + 1) {
            h = 9 if i % 8 == 0 else (7 if i % 4 == 0 else (5 if i % 2 == 0 else 3.5))
            tick = Line((margin + i * 1 in / 8, 0), (margin + i * 1 in / 8, h))
        }
        for k in range(floor(inches / 8) + 1) {
            label = Text(str(k), (margin + k * 1 in, 11), size=4)
        }
        unit = Text("in", (margin + scale_len + tail / 2, 6), size=3)
    }

    # both scales start at the zero mark; their ticks start on the bar's edges
    metric.tick[0].start.x == bar.bb.left + margin
    Coincident(metric.tick[0].start, bar.top)
    imperial.tick[0].start.x == metric.tick[0].start.x
    Coincident(imperial.tick[0].start, bar.bottom)
    # the hanging hole is centered in the tail
    AlignCenterY(hang, bar)
    hang.bb.center_x == bar.bb.right - tail / 2
}
