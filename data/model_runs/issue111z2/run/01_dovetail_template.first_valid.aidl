# Workshop: a dovetail marking template, 3 mm clear acrylic. A flat trapezoid plate: bottom
# edge 120 mm, height 60 mm; the left edge leans in at 1:6 (10 mm over the 60 mm height, for
# hardwood), the right edge at 1:8 (7.5 mm over 60 mm, for softwood); corners sharp (they are
# the marking edges). A 6 mm hanging hole centred 10 mm below the top edge. Engraved: "1:6"
# beside the left edge and "1:8" beside the right edge (5 mm stroke text, 30 mm up), the word
# "DOVETAIL" in sans outline letters 8 mm high, filled, centred 32 mm up; a ruler along the
# bottom edge: ticks every 5 mm from 10 mm to 110 mm, 6 mm long every 10 mm, 3 mm between.

units mm
thickness 3 mm

param base = 120 mm, min = 80, max = 200
param h = 60 mm, min = 40, max = 100

run6 = h / 6
run8 = h / 8

solid template {
    body = Polygon([(0, 0), (base, 0), (base - run8, h), (run6, h)])

    hole hang {
        c = Circle(center=(base / 2, h - 10), diameter=6)
    }

    drawing marks {
        slope6 = Text("1:6", position=(14, 30), size=5, anchor="start")
        slope8 = Text("1:8", position=(base - 14, 30), size=5, anchor="end")
        word = Text("DOVETAIL", position=(base / 2, 32), size=8, font="sans", fill=true)
        for i in range(21) {
            tick = Line((10 + i * 5, 0), (10 + i * 5, 6 if i % 2 == 0 else 3))
        }
    }

    # the request's own numbers
    assert body.bb.width == 120 mm, "bottom edge 120 mm"
    assert body.bb.height == 60 mm, "height 60 mm"
    assert body.points[3].x - body.points[0].x == 10 mm, "1:6 slope: 10 mm over the height"
    assert body.points[1].x - body.points[2].x == 7.5 mm, "1:8 slope: 7.5 mm over the height"
    assert body.bb.top - hang.c.center.y == 10 mm, "hanging hole 10 mm below the top"
    assert hang.c.diameter == 6 mm, "6 mm hanging hole"
    assert len(marks.tick) == 21, "ticks every 5 mm from 10 to 110"
}
