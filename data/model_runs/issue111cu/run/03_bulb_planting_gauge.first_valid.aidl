# Request (garden): a bulb-planting depth gauge, 3 mm acrylic, to stand in the planting hole.
# A stick 50 mm wide and 270 mm long with a fully rounded top end and a 10 mm hanging hole
# 25 mm below the top. A centimetre scale from the flat bottom end (0) up to 20 cm: engraved
# ticks on the left edge every 1 cm, 6 mm long, and 12 mm long every 5 cm with the number
# (5, 10, 15, 20; 5 mm tall) beside them. On the right edge a V notch (4 mm tall, 3 mm deep)
# at each bulb's planting depth, with the bulb's name engraved just above a line from the
# middle of the stick to the notch: SNOWDROP 5 cm, CROCUS 8 cm, HYACINTH 10 cm, TULIP 15 cm,
# ALLIUM 20 cm. "BULB" over "DEPTH cm" engraved on the handle, 5 mm tall.

thickness 3 mm
min_wall 0.5 mm

W = 50 mm
LEN = 270 mm
bulbs = [["SNOWDROP", 50], ["CROCUS", 80], ["HYACINTH", 100], ["TULIP", 150], ["ALLIUM", 200]]

solid gauge {
    body = RoundedRectangle(bottom_left=(-W / 2, 0), width=W, height=LEN,
                            corner_radii=[W / 2, W / 2, 0, 0])
    hole hang {
        c = Circle(center=(0, LEN - 25 mm), diameter=10)
    }
    hole notches {
        for b in bulbs {
            v = Polygon([(W / 2 + 1, b[1] - 2), (W / 2 + 1, b[1] + 2), (W / 2 - 3, b[1])])
        }
    }
    drawing scale {
        for i in range(1, 21) {
            tick = Line((-W / 2, i * 10 mm), (-W / 2 + (12 mm if i % 5 == 0 else 6 mm), i * 10 mm))
        }
        for j in range(1, 5) {
            num = Text(str(j * 5), position=(-W / 2 + 14 mm, j * 50 mm), size=5, anchor="start",
                       valign="middle")
        }
        for b in bulbs {
            mark = Line((0, b[1]), (W / 2 - 3, b[1]))
            name = Text(b[0], position=(W / 2 - 2, b[1] + 1), size=3.5, anchor="end",
                        valign="bottom")
        }
        title1 = Text("BULB", position=(0, 225), size=5, valign="middle")
        title2 = Text("DEPTH cm", position=(0, 216), size=5, valign="middle")
    }
    Fixed(body)

    assert body.bb.width == 50 mm and body.bb.height == 270 mm, "stick 50 x 270"
    assert body.bb.top - hang.c.center.y == 25 mm, "hanging hole 25 mm below the top"
    assert len(scale.tick) == 20, "ticks every cm to 20 cm"
    assert scale.tick[4].end.x - scale.tick[4].start.x == 12 mm, "5 cm tick 12 mm"
    assert scale.tick[0].end.x - scale.tick[0].start.x == 6 mm, "1 cm tick 6 mm"
    assert scale.tick[19].start.y - body.bb.bottom == 200 mm, "20 cm from the bottom"
    assert len(notches.v) == 5, "five bulbs"
    assert scale.mark[3].start.y - body.bb.bottom == 150 mm, "tulip at 15 cm"
    assert scale.mark[1].start.y - body.bb.bottom == 80 mm, "crocus at 8 cm"
}
