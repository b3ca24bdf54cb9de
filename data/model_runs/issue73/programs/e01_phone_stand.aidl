# A flat-pack phone stand: two side profiles (slanted back, front lip) and a cross bar.
param t = 3 mm
assembly stand {
    solid side {
        profile = Polygon([(0, 0), (80, 0), (80, 6), (30, 6), (30, 14), (24, 14), (20, 6), (10, 6), (45, 90), (38, 92), (0, 6)])
        hole slot { s = Rectangle(center=(60, 3), width=t, height=6) }
    }
    side2 = Mirrored(side, about=Line((100, 0), (100, 10), construction=true))
    solid bar {
        b = Rectangle(center=(0, -30), width=70, height=12)
    }
    Below(bar, side, gap=5)
}
