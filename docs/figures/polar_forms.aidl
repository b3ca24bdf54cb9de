# Figure of docs/language.md: Line and Slot by length and angle, a Rectangle along a segment, At.
# Drawn by `python docs/make_pictures.py` to docs/images/polar_forms.png.
# render: --png-width 333

solid link {
    base = Rectangle(bottom_left=(0, 0), width=80, height=45)
    Fixed(base)
    hole slot { s = Slot(start=(10, 34), length=24, angle=-20 deg, width=5) }
    hole bar { b = Rectangle(start=(40, 8), end=(66, 30), width=4) }
    hole pin { c = Circle(center=(0, 0), radius=2) }
    At(pin.c.center, base.top_right, dx=-7, dy=-7)
    drawing scribe { l = Line(start=(8, 8), length=25, angle=30 deg) }
}
