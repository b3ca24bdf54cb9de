# Tablet stand side: a trapezoid 150 mm along the bottom, 90 mm along the top,
# 80 mm tall, with two 10 mm wide slots cut down into it from the top edge to
# hold a tablet: slot A leans back 20 degrees from vertical (110 deg from +x)
# with its round bottom's center 30 mm below the top edge and 20 mm left of
# the side's center line; slot B leans back 30 degrees (120 deg from +x) with
# its bottom's center 30 mm below the top edge, 25 mm right of the center line.

param depth = 30 mm, min = 20 mm, max = 40 mm
param slot_w = 10 mm, min = 6 mm, max = 14 mm

solid side {
    body = Trapezoid(center=(0, 0), bottom_width=150, top_width=90, height=80)
    hole slot_a {
        s = Slot(start=(-20, 10), length=50, angle=110 deg, width=slot_w)
    }
    hole slot_b {
        s = Slot(start=(25, 10), length=50, angle=120 deg, width=slot_w)
    }
    At(slot_a.s.start, body.top.midpoint, dx=-20, dy=-depth)
    At(slot_b.s.start, body.top.midpoint, dx=25, dy=-depth)

    assert body.bb.width == 150 mm and body.bb.height == 80 mm, "side size"
    assert body.top.midpoint.y - slot_a.s.start.y == 30 mm, "slot A depth"
}
