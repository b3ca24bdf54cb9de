# Figure of docs/language.md: Bezier: a heart from four cubic segments (control points
# marked, their handles drawn), an open Bezier closed by a Line, and a Stroke along a wave.
# Drawn by `python docs/make_pictures.py` to docs/images/bezier.png.

heart = [(0, -20), (20, -5), (25, 15), (12, 18), (5, 20), (0, 15), (0, 10),
         (0, 15), (-5, 20), (-12, 18), (-25, 15), (-20, -5), (0, -20)]

assembly beziers {
    solid valentine {
        body = Bezier(points=heart, closed=true)
        hole eye { c = Circle(center=(0, 2), radius=4) }
    }
    drawing handles {          # each end point joined to its control points
        for i in range(0, 12, 3) {
            a = Line(start=heart[i], end=heart[i + 1])
            b = Line(start=heart[i + 2], end=heart[i + 3])
            m = Circle(center=heart[i], radius=0.8)
        }
    }
    solid tab {
        top = Bezier(points=[(40, -10), (40, 25), (80, 25), (80, -10)])
        bottom = Line(start=top.end, end=top.start)
    }
    solid band {
        wave = Bezier(points=[(95, 0), (100, 15), (110, -15), (115, 0), (120, 15), (130, -15),
                              (135, 0)])
        s = Stroke(wave, width=3)
    }
}
