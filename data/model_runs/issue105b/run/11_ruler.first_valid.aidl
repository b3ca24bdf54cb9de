# 15 cm ruler, 3 mm acrylic: a 170 x 30 mm strip with 2 mm rounded corners. The
# scale starts 10 mm in from the left end: 151 engraved ticks 1 mm apart hanging
# from the top edge: 4 mm long at each mm, 6 mm at each 5 mm, 9 mm at each cm;
# the numbers 0 to 15, 3.5 mm tall, centered under each cm tick, 2 mm below it.
# A 6 mm hanging hole centered at the right end, 7 mm in from the edge.

units mm
thickness 3 mm

param n_mm = 150, min = 50, max = 150

solid ruler {
    body = RoundedRectangle(center=(0, 0), width=170, height=30, corner_radius=2)

    drawing scale {
        for i in range(n_mm + 1) {
            t = Line(start=(i, 0), end=(i, -4))
        }
    }
    drawing numbers {
        for c in range(n_mm // 10 + 1) {
            num = Text(str(c), position=(10 * c, -12), size=3.5, valign="top")
        }
    }
    for i in range(n_mm + 1) {
        L = 9 if i % 10 == 0 else (6 if i % 5 == 0 else 4)
        At(scale.t[i].start, body.top_left, dx=10 + i)
        At(scale.t[i].end, body.top_left, dx=10 + i, dy=-L)
    }
    for c in range(n_mm // 10 + 1) {
        At(numbers.num[c].position, scale.t[10 * c].end, dy=-2)
    }

    hole hang {
        h = Circle(center=(78, 0), diameter=6)
    }
    AlignCenterY(hang, body)
    HorizontalDistance(hang.h.center, body.right.midpoint, 7)
}
