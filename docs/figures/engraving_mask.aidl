# Figure of docs/language.md: a compass rose, the intercardinal points drawn behind the cardinal
# ones (a hole in a drawing). Drawn by `python docs/make_pictures.py` to docs/images/engraving_mask.png.
# render: --png-width 360
def point(a, tip, side, spread) -> drawing {
    p = Polygon(points=[(0, 0), (side * cos(a - spread), side * sin(a - spread)),
                        (tip * cos(a), tip * sin(a)), (side * cos(a + spread), side * sin(a + spread))])
}
solid plate {
    disc = Circle(center=(0, 0), radius=50)
    drawing rose {
        drawing back {            # the four intercardinal points, behind
            for i in range(4) { p = point(45 deg + i * 90 deg, 30, 7, 25 deg) }
            hole covered {        # hides what the cardinal points cover
                for i in range(4) { hole q = point(i * 90 deg, 42, 8, 30 deg) }
            }
        }
        drawing front {           # the four cardinal points, drawn whole
            for i in range(4) { q = point(i * 90 deg, 42, 8, 30 deg) }
        }
    }
}
