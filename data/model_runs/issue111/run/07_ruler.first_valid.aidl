# 15 cm ruler: a 170 x 30 mm strip with 3 mm rounded corners; millimetre ticks 0..150
# engraved along the bottom edge from x = 10 mm in: 4 mm long, every 5 mm 6 mm long,
# every 10 mm 9 mm long with its centimetre number (3 mm text) above it; "cm" at the
# left end; a 6 mm hanging hole centred 7 mm in from the right end.

param n = 150
solid ruler {
    body = RoundedRectangle(bottom_left=(0, 0), width=170, height=30, corner_radius=3)
    drawing scale {
        for i in range(n + 1) {
            tick = Line((10 + i, 0), (10 + i, 9 if i % 10 == 0 else (6 if i % 5 == 0 else 4)))
        }
        for k in range(n // 10 + 1) {
            num = Text(str(k), position=(10 + 10 * k, 11), size=3)
        }
        unit = Text("cm", position=(3, 20), size=3, anchor="start")
    }
    hole hang {
        c = Circle(center=(163, 22), diameter=6)
    }
    assert len(scale.tick) == 151, "151 ticks"
    assert len(scale.num) == 16, "numbers 0..15"
    assert scale.tick[150].start.x - scale.tick[0].start.x == 150 mm, "150 mm scale"
    assert hang.c.center.x == body.bb.right - 7 mm, "hole 7 mm from the right end"
    assert hang.bb.bottom > scale.num[15].bb.top + 1 mm, "hole above the numbers"
}
assert ruler.body.bb.width == 170 mm and ruler.body.bb.height == 30 mm, "170 x 30"
