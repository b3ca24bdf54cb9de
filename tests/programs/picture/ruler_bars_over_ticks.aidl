# A 10 cm ruler whose centimetre scale is drawn as outlined bars (alternate
# centimetres) over the millimetre ticks: the ticks run into and through the
# bars' outlines, engraving on engraving (issue 84).
solid ruler {
    bar = Rectangle(center=(60, 15), width=120, height=30)
    drawing ticks {
        for i in range(101) {
            h = 8 if i % 10 == 0 else (6 if i % 5 == 0 else 4)
            tick = Line((10 + i * 1 mm, 30), (10 + i * 1 mm, 30 - h))
        }
    }
    drawing bars {
        for k in range(5) {
            cm = Rectangle(center=(15 + k * 20 mm, 25), width=10, height=3)
        }
    }
}
