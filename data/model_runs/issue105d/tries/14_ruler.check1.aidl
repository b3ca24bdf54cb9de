# 150 mm ruler: a 170 x 30 mm strip with 3 mm rounded corners; engraved ticks every
# 10 mm from 0 to 150 (16 ticks) hanging from 1 mm below the top edge, the 0 tick 5 mm from
# the left end; ticks 7 mm long, every fifth (0, 50, 100, 150) 11 mm; the centimetre numbers
# 0..15 engraved 3.5 mm tall under each tick; a 5 mm hanging hole at the right end,
# 7 mm from the end, at mid-height.
param length = 150 mm, min = 100 mm, max = 300 mm
thickness 3 mm

solid ruler {
    body = RoundedRectangle(bottom_left=(0, 0), width=length + 20, height=30, corner_radius=3)
    drawing scale {
        for i in range(16) {
            tick = Line((5 + i * 10, 29), (5 + i * 10, 29 - (11 if i % 5 == 0 else 7)))
            num = Text(str(i), (5 + i * 10, 14), size=3.5, valign="top")
        }
    }
    Rigid(scale)
    At(scale.tick[0].start, body.bb.top_left, dx=5, dy=-1)
    hole hang { c = Circle(center=(163, 15), diameter=5) }
    At(hang.c.center, (body.bb.right - 7, body.bb.center_y))
    Fixed(body)
    assert len(scale.tick) == 16, "16 ticks, 0 to 150"
    assert scale.tick[15].start.x - scale.tick[0].start.x == 150 mm, "150 mm scale"
    assert scale.tick[1].start.x - scale.tick[0].start.x == 10 mm, "every 10 mm"
    assert hang.bb.left > scale.tick[15].start.x + 3 mm, "hole clear of the last tick"
}
