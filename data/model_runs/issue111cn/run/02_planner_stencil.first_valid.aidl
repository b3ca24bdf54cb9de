# Request (office): a planner (bullet-journal) stencil cut from 0.5 mm PET sheet, 180 x 70 mm
# with 5 mm corner radius. Openings cut through: a row of seven 5 mm check boxes at 8 mm pitch,
# under them the day letters M T W T F S S (6 mm bold letters, one under each box), a row of
# circles of 3, 4, 5, 6, 8 and 10 mm with 3 mm between them, a 50 x 8 mm rounded banner,
# a right-pointing arrow 19 mm long, a heart about 13 mm tall, a 110 mm long 1.5 mm pen slot
# for underlining, and a 20 mm thumb hole at the right end. Along the bottom edge an engraved
# 150 mm ruler: a tick every mm (2.5 mm long), 4 mm at every 5 mm, 6 mm at every cm, numbered
# 0 to 15 in 2.5 mm figures.

thickness 0.5 mm

param pitch = 8 mm, min = 7 mm, max = 10 mm

circle_d = [3, 4, 5, 6, 8, 10]
circle_x = [-18.5, -12, -4.5, 4, 14, 26]
days = ["M", "T", "W", "T", "F", "S", "S"]

solid stencil {
    body = RoundedRectangle(center=(0, 0), width=180, height=70, corner_radius=5)

    hole boxes {
        for i in range(7) {
            b = Rectangle(center=(-80 + i * pitch, 22), width=5, height=5)
        }
    }
    hole letters {
        for i in range(7) {
            d = Text(days[i], position=(-80 + i * pitch, 12), size=6, font="sans:Bold",
                     valign="middle")
        }
    }
    hole circles {
        for i in range(6) {
            c = Circle(center=(circle_x[i], 22), diameter=circle_d[i])
        }
    }
    hole banner {
        r = RoundedRectangle(center=(5, 4), width=50, height=8, corner_radius=4)
    }
    hole arrow {
        a = Polygon([(35, 2), (47, 2), (47, -1), (54, 4), (47, 9), (47, 6), (35, 6)])
    }
    hole heart {
        lobe_l = Hull(Circle(center=(56, -10), radius=4.5), Point(60, -19))
        lobe_r = Hull(Circle(center=(64, -10), radius=4.5), Point(60, -19))
    }
    hole pen_slot {
        s = Slot(center=(-25, -12), length=110, width=1.5)
    }
    hole thumb {
        c = Circle(center=(72, 10), diameter=20)
    }

    drawing ruler {
        for i in range(151) {
            tick = Line((-80 + i, -35), (-80 + i, -35 + (6 if i % 10 == 0 else (4 if i % 5 == 0 else 2.5))))
        }
        for k in range(16) {
            n = Text(str(k), position=(-80 + k * 10, -27), size=2.5)
        }
    }

    assert body.width == 180 mm and body.height == 70 mm, "stencil 180 x 70"
    assert len(boxes.b) == 7, "seven check boxes"
    assert boxes.b[1].center.x - boxes.b[0].center.x == 8 mm, "8 mm pitch"
    assert len(circles.c) == 6
    assert circles.c[1].bb.left - circles.c[0].bb.right == 3 mm, "3 mm between circles"
    assert circles.c[5].bb.left - circles.c[4].bb.right == 3 mm, "3 mm between circles"
    assert len(ruler.tick) == 151, "a tick every mm over 150 mm"
    assert ruler.tick[150].start.x - ruler.tick[0].start.x == 150 mm
    assert arrow.a.bb.width == 19 mm
    assert pen_slot.s.length == 110 mm
    assert thumb.c.diameter == 20 mm
}
