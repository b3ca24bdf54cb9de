# Request (sport): a golf putting mirror for eye-line practice, cut from 3 mm mirror acrylic,
# 300 x 120 mm with 10 mm rounded corners. A 42 mm round opening for the ball, its centre on
# the long centre line 60 mm from the left end. Engraved: an aim line along the long centre
# line from 5 mm inside each end, stopping 3 mm short of the opening on both sides; an eye box
# 70 x 56 mm centred on the ball; a distance scale along the top edge, ticks every 10 mm from
# the ball's centre to 220 mm right of it, 3 mm long, every fifth 6 mm long and numbered in cm
# (0, 5, 10, 15, 20; 3.5 mm strokes) under the tick; "EYES OVER THE BALL" (4 mm strokes)
# centred 10 mm above the bottom edge, 120 mm right of the ball's centre. Four 5 mm holes for
# tee pegs to pin it down, 15 mm in from each corner.

units mm
thickness 3 mm

solid mirror {
    body = RoundedRectangle(center=(0, 0), width=300, height=120, corner_radius=10)
    hole ball { c = Circle(center=(-90, 0), diameter=42) }
    hole tee { c = Circle(center=(0, 0), diameter=5) }
    tees = CornerPattern(tee, body, inset=15)

    drawing marks {
        aim_l = Line((-145, 0), (-90 - 21 - 3, 0))
        aim_r = Line((-90 + 21 + 3, 0), (145, 0))
        eye = Rectangle(center=(-90, 0), width=70, height=56)
        for i in range(23) {
            tick = Line((-90 + 10 * i, 60), (-90 + 10 * i, 60 - (6 if i % 5 == 0 else 3)))
        }
        for j in range(5) {
            cm = Text(str(5 * j), position=(-90 + 50 * j, 60 - 6 - 1 - 3.5), size=3.5)
        }
        words = Text("EYES OVER THE BALL", position=(-90 + 120, -60 + 10), size=4, valign="middle")
    }

    # the request's numbers
    assert body.width == 300 mm and body.height == 120 mm, "300 x 120"
    assert ball.c.diameter == 42 mm, "42 mm ball opening"
    assert ball.c.center.x - body.bb.left == 60 mm and ball.c.center.y == body.center.y, "ball 60 mm from the left end, on the centre line"
    assert marks.aim_l.start.x - body.bb.left == 5 mm and body.bb.right - marks.aim_r.end.x == 5 mm, "aim line 5 mm inside the ends"
    assert (ball.c.center.x - ball.c.radius) - marks.aim_l.end.x == 3 mm, "aim line stops 3 mm short (left)"
    assert marks.aim_r.start.x - (ball.c.center.x + ball.c.radius) == 3 mm, "aim line stops 3 mm short (right)"
    assert marks.eye.width == 70 mm and marks.eye.height == 56 mm and marks.eye.center.x == ball.c.center.x, "eye box on the ball"
    assert len(marks.tick) == 23 and marks.tick[22].start.x - ball.c.center.x == 220 mm, "ticks to 220 mm"
    assert marks.tick[5].start.y - marks.tick[5].end.y == 6 mm and marks.tick[1].start.y - marks.tick[1].end.y == 3 mm, "tick lengths"
    assert marks.words.position.x - ball.c.center.x == 120 mm and marks.words.position.y - body.bb.bottom == 10 mm, "the words' place"
    assert tees[0].c.center.x - body.bb.left == 15 mm and tees[0].c.center.y - body.bb.bottom == 15 mm, "tee holes 15 mm in"
    assert distance(marks.cm, tee) >= 2 mm and distance(marks.tick, tees[2]) >= 2 mm, "scale clear of the tee holes"
    assert distance(marks.eye, ball) >= 5 mm, "eye box clear of the opening"
}
