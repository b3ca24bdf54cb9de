# Figure of docs/language.md: a closed Spline through six points (marked) with a hole, a Spline cut by a hole and a flat, and an open Spline closed by a Line.
# Drawn by `python docs/make_pictures.py` to docs/images/spline.png.
# render: --png-width 654

units mm
leaf_points = [(0, -25), (18, -8), (14, 14), (0, 28), (-14, 14), (-18, -8)]
assembly splines {
    solid leaf {
        body = Spline(points=leaf_points, closed=true)
        hole eye { c = Circle(center=(0, 2), radius=5) }
    }
    drawing marks {            # the points the spline passes through
        for p in leaf_points {
            m = Circle(center=p, radius=1)
        }
    }
    solid pick {
        body = Spline(points=[(50, -25), (68, 0), (62, 20), (38, 20), (32, 0)], closed=true)
        hole notch { c = Circle(center=(68, 0), radius=5) }
        hole flat { r = Rectangle(center=(50, 26), width=40, height=10) }
    }
    solid tab {
        top = Spline(points=[(85, -10), (95, 12), (105, 18), (115, 12), (125, -10)])
        bottom = Line(start=top.end, end=top.start)
        drawing wave {
            w = Spline(through=[(92, -5), (98, 0), (105, -5), (112, 0), (118, -5)])
        }
    }
}
