# protractor: half disc R80, ticks every 10 deg, labels 0..180
param R = 80 mm
solid protractor {
    half = Arc(center=(0, 0), radius=R, start_angle=0, end_angle=180)
    base = Line((-R, 0), (R, 0))
    Coincident(half.start, base.end)
    Coincident(half.end, base.start)
    Fixed(half)
    drawing ticks {
        for i in range(19) {
            a = i * 10
            tk = Line(start=(R * cos(a), R * sin(a)), length=8, angle=a + 180)
            lb = Text(str(a), ((R - 15) * cos(a), (R - 15) * sin(a)), size=4, valign="middle", rotation=a - 90)
        }
    }
}
