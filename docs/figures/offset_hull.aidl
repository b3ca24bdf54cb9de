# Figure of docs/language.md: a Shell cookie cutter, a Hull belt around two pulleys, a Star grown by 3 mm, a tag with corner_radii and a mitered Inset window.
# Drawn by `python docs/make_pictures.py` to docs/images/offset_hull.png.
# render: --png-width 654

units mm
assembly shapes {
    solid cutter {
        heart = Polygon([(0, 0), (20, 20), (10, 30), (0, 22), (-10, 30), (-20, 20)])
        wall = Shell(heart, 2)
    }
    solid belt {
        big = Circle(center=(45, 15), radius=12)
        small = Circle(center=(85, 15), radius=6)
        loop = Hull(big, small)
        hole bore { c = Circle(center=(45, 15), radius=4) }
    }
    solid star {
        s = Star(center=(-50, 15), points=5, outer_radius=14, inner_radius=6)
        round = Offset(s, 3)
    }
    solid tag {
        t = RoundedRectangle(center=(20, -25), width=60, height=24, corner_radii=[10, 0, 10, 0])
        hole window {
            r = Rectangle(center=(20, -25), width=60, height=24)
            w = Inset(r, 5, join="miter")
        }
    }
}
