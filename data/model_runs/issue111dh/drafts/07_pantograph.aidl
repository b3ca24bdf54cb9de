# Request (science): a drawing pantograph that enlarges x2, x3 or x4, 3 mm acrylic, M4 pivots.
# Four bars 18 mm wide with round ends, all holes 4.2 mm (M4) except the pen hole (10 mm).
# Long bar F-B: 300 mm between its end holes F (the fixed pivot) and B, with setting holes A
# at 150 (x2), 100 (x3) and 75 mm (x4) from F. Long bar B-P: 300 mm from B to the 10 mm pen
# hole P, setting holes C at 150 (x2), 100 (x3) and 75 mm (x4) from B. Short bar T-A: from the
# tracer hole T, settings at 75 (x4), 100 (x3) and 150 mm (x2), the bar ending at 150.
# Short bar T-C: from T, settings at 150 (x2), 200 (x3) and 225 mm (x4), ending at 225 (the two
# short bars' settings for one scale add up to 300). Each setting hole labelled ("x2") 4 mm tall
# just left of it, each bar its name 5 mm tall. A base 80 x 50, R6, with the F pivot hole 20 mm
# right of its centre and two 4.5 mm countersunk screw holes (9 mm heads) 25 mm left of its
# centre, 13 mm above and below, to screw it to the drawing board; "PANTOGRAPH" engraved on it.

units mm
thickness 3 mm

L = 300 mm
bar_w = 18 mm
pin_d = 4.2 mm
pen_d = 10 mm

def bar(length=300 mm, holes=[75, 100, 150], labels=["x4", "x3", "x2"], end_d=4.2 mm,
        name="", name_x=225 mm) -> solid {
    body = Slot(start=(0, 0), end=(length, 0), width=bar_w)
    hole pivot { c = Circle(center=(0, 0), diameter=pin_d) }
    for i in range(len(holes)) {
        hole setting { c = Circle(center=(holes[i], 0), diameter=pin_d) }
    }
    if end_d > 0 {
        hole far_end { c = Circle(center=(length, 0), diameter=end_d) }
    }
    drawing marks {
        for i in range(len(holes)) {
            lab = Text(labels[i], position=(holes[i] - 5, 0), size=4, anchor="end",
                       valign="middle")
        }
        title = Text(name, position=(name_x, 0), size=5, valign="middle")
    }
}

assembly pantograph {
    fb = bar(length=L, name="F-B", name_x=225)
    bp = bar(length=L, end_d=pen_d, name="B-P", name_x=225)
    ta = bar(length=150, holes=[75, 100, 150], labels=["x4", "x3", "x2"], end_d=0, name="T-A",
             name_x=37)
    tc = bar(length=225, holes=[150, 200, 225], labels=["x2", "x3", "x4"], end_d=0, name="T-C",
             name_x=75)
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=80, height=50, corner_radius=6)
        hole pivot { c = Circle(center=(20, 0), diameter=pin_d) }
        for s in [-1, 1] {
            hole screw { c = Circle(center=(-25, s * 13), diameter=4.5) }
        }
        Countersink(screw, diameter=9)
        drawing name { t = Text("PANTOGRAPH", position=(0, -19), size=4, valign="middle") }
    }

    # flat on the sheet: the bars one under another, the base beside the short ones
    Below(bp, fb, gap=6)
    Below(ta, bp, gap=6)
    Below(tc, ta, gap=6)
    AlignLeft(bp, fb)
    AlignLeft(ta, fb)
    AlignLeft(tc, fb)
    # FIX after the first valid program: W0511, the 50 mm base beside T-A hung down over T-C
    # (225 long); put it right of T-C, the longer of the two
    RightOf(base, tc, gap=10)
    AlignTop(base, ta)

    # assembled at x2: F at the origin, F-B at +30 deg, B-P at -30 deg; T and P then lie on
    # the x axis, P twice as far from F as T. Layers: base, F-B, then T-A and B-P, then T-C.
    Place(base, position=(-20, 0, 0))
    Place(fb, position=(0, 0, 3), rotation=(0, 0, 30 deg))
    Place(bp, position=(L * cos(30 deg), L * sin(30 deg), 6), rotation=(0, 0, -30 deg))
    Place(ta, position=(L * cos(30 deg), 0, 6), rotation=(0, 0, 150 deg))
    Place(tc, position=(L * cos(30 deg), 0, 9), rotation=(0, 0, 30 deg))

    # the request's numbers
    assert fb.far_end.c.center.x - fb.pivot.c.center.x == 300 mm, "F to B 300"
    assert bp.far_end.c.center.x - bp.pivot.c.center.x == 300 mm, "B to P 300"
    assert bp.far_end.c.diameter == 10 mm and fb.far_end.c.diameter == 4.2 mm, "pen hole 10"
    assert fb.setting[0].c.center.x - fb.pivot.c.center.x == 75 mm and
        fb.setting[1].c.center.x - fb.pivot.c.center.x == 100 mm and
        fb.setting[2].c.center.x - fb.pivot.c.center.x == 150 mm, "A at 75, 100, 150"
    assert ta.setting[2].c.center.x - ta.pivot.c.center.x == 150 mm, "T-A ends at 150"
    assert tc.setting[2].c.center.x - tc.pivot.c.center.x == 225 mm, "T-C ends at 225"
    for i in range(3) {
        # one scale's settings on the two short bars add up to 300 (x4: 75 + 225 ...)
        assert (ta.setting[i].c.center.x - ta.pivot.c.center.x) +
            (tc.setting[2 - i].c.center.x - tc.pivot.c.center.x) == 300 mm, "short bars add to 300"
    }
    assert fb.body.width == 18 mm, "bars 18 wide"
    assert base.plate.bb.width == 80 mm and base.plate.bb.height == 50 mm, "base 80 x 50"
    assert base.pivot.c.center.x - base.plate.center.x == 20 mm, "pivot 20 right"
    assert base.screw[1].c.center.y - base.screw[0].c.center.y == 26 mm, "screws +-13"
}
