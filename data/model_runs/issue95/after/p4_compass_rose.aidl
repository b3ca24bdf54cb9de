# A compass rose engraved on a round coaster: four long cardinal points in
# front, four shorter intercardinal points behind them (hidden where the front
# points cover them), an N above the north point.
units mm

def point(a, tip, side, spread) -> drawing {
    p = Polygon(points=[(0, 0), (side * cos(a - spread), side * sin(a - spread)),
                        (tip * cos(a), tip * sin(a)), (side * cos(a + spread), side * sin(a + spread))])
}

solid coaster {
    disc = Circle(center=(0, 0), radius=50)
    drawing rose {
        drawing back {
            for i in range(4) { p = point(45 deg + i * 90 deg, 28, 8, 22 deg) }
            hole covered {
                for i in range(4) { hole q = point(i * 90 deg, 40, 9, 25 deg) }
            }
        }
        drawing front {
            for i in range(4) { q = point(i * 90 deg, 40, 9, 25 deg) }
        }
        n = Text("N", position=(0, 43), size=5)
    }
    Fixed(disc.center)
}
