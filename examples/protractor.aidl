# A 180-degree protractor: a half disc (Sector) on a straight base, an
# annulus-segment window, degree ticks, and numbers laid along arcs (Text along=),
# outer scale counter-clockwise, inner scale clockwise. Ticks and numbers are
# engraved.
# Try: --set radius=100

param radius = 80 mm, min = 75 mm, max = 160 mm, step = 1 mm
base_height = 8 mm

solid protractor {
    body = Sector(center=(0, 0), radius=radius, start_angle=0 deg, end_angle=180 deg)
    base = Rectangle(bottom_left=(-radius, -base_height), width=2 * radius, height=base_height)
    Fixed(body)
    Coincident(base.top_left, (-radius, 0))

    # a window to see the work through: an annulus segment
    hole window {
        w = Sector(center=(0, 0), radius=0.55 * radius, inner_radius=0.3 * radius,
                   start_angle=20 deg, end_angle=160 deg)
    }
    hole pivot {
        c = Circle(center=(0, 0), radius=1)
    }
    Coincident(window.w.center, body.center)
    Coincident(pivot.c.center, body.center)

    # a tick every degree, longer every 5 and 10, hanging in from the arc
    drawing ticks {
        for i in range(181) {
            h = 8 if i % 10 == 0 else (5.5 if i % 5 == 0 else 3.5)
            tick = Line(start=(radius * cos(i * 1 deg), radius * sin(i * 1 deg)), length=h,
                        angle=i * 1 deg + 180 deg)
        }
        left_datum = Line((-0.65 * radius, 0), (-2, 0))
        right_datum = Line((2, 0), (0.65 * radius, 0))
    }
    Coincident(ticks.tick[0].start, body.start)

    # numbers along two arcs, upright: no cos/sin for their places
    drawing numbers {
        outer = Circle(center=(0, 0), radius=radius - 13, construction=true)
        inner = Circle(center=(0, 0), radius=radius - 23, construction=true)
        for a in range(0, 181, 10) {
            n = Text(str(a), along=outer, angle=a * 1 deg, size=3)
            m = Text(str(180 - a), along=inner, angle=a * 1 deg, size=2.5)
        }
        title = Text("DEGREES", position=(0, -base_height / 2), size=3, valign="middle")
    }
    Coincident(numbers.outer.center, body.center)
}
