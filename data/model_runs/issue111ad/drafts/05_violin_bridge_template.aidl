# Music: a tracing template for carving a full-size (4/4) violin bridge, from
# 2 mm clear acrylic. Feet 41.5 mm across overall, each foot 10.25 mm wide, with
# an arch between them 6 mm high at the middle. The sides curve in to a waist
# 27 mm across at 16 mm up and out again; the top is a smooth curve from the
# G (bass, left) corner 33 mm tall, 37 mm apart from the E (treble, right)
# corner 30.5 mm tall, highest (34.5 mm) in the middle. A heart opening (two
# 4.4 mm lobes at 19 mm up, its point at 13 mm up) and two kidney slots
# (7 x 3 mm, 9 mm either side of the centre at 11 mm up, leaning in at 70 deg).
# Engraved: 4 string marks 11.3 mm apart, 3 mm long, ending 26-29 mm up, and
# "4/4" 3 mm high over the arch.

units mm
thickness 2 mm

solid bridge {
    outline = Spline([(-20.75, 0), (-10.5, 0), (0, 6), (10.5, 0), (20.75, 0),
                      (19, 8), (13.5, 16), (17, 22), (18.5, 30.5),
                      (0, 34.5),
                      (-18.5, 33), (-17, 23), (-13.5, 16), (-19, 8)],
                     closed=true, corners=[0, 1, 3, 4, 8, 10])

    hole heart {
        lobe_l = Hull(Circle(center=(-2, 19), radius=2.2), Point(0, 13))
        lobe_r = Hull(Circle(center=(2, 19), radius=2.2), Point(0, 13))
    }

    hole kidneys {
        left = Slot(center=(-9, 11), length=7, width=3, rotation=70)
        right = Slot(center=(9, 11), length=7, width=3, rotation=110)
    }

    drawing marks {
        for i in range(4) {
            mark = Line(start=(-17 + i * 11.3, 26), end=(-17 + i * 11.3, 29))
        }
        size = Text("4/4", position=(0, 8.5), size=3)
    }

    assert outline.points[4].x - outline.points[0].x == 41.5 mm, "feet 41.5 across"
    assert outline.points[1].x - outline.points[0].x == 10.25 mm, "foot 10.25 wide"
    assert outline.points[2].y == 6 mm, "arch 6 high"
    assert outline.points[6].x - outline.points[12].x == 27 mm, "waist 27 across"
    assert outline.points[10].y == 33 mm, "G corner 33 tall"
    assert outline.points[8].y == 30.5 mm, "E corner 30.5 tall"
    assert outline.points[8].x - outline.points[10].x == 37 mm, "top corners 37 apart"
    assert outline.points[9].y == 34.5 mm, "34.5 at the middle"
    assert len(marks.mark) == 4, "four strings"
    assert marks.mark[3].start.x - marks.mark[0].start.x == 3 * 11.3 mm, "string marks 11.3 apart"
}
