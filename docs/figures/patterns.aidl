# Figure of docs/language.md: GridPattern, CornerPattern and CircularPattern(start_angle=).
# Drawn by `python docs/make_pictures.py` to docs/images/patterns.png.
# render: --png-width 499

solid plate {
    body = Rectangle(center=(0, 0), width=120, height=70)
    hole h { c = Circle(center=(0, 0), diameter=5) }
    CornerPattern(h, body, inset=7)
    hole vent { v = Slot(center=(-40, -15), length=10, width=3, rotation=90 deg) }
    vents = GridPattern(vent, rows=3, cols=4, spacing=(8, 15))
    hole bolt { b = Circle(center=(42, 0), diameter=4) }
    bolts = CircularPattern(bolt, 6, center=(30, 0), start_angle=30 deg)
    hole bore { c = Circle(center=(30, 0), diameter=12) }
    Fixed(body)
}
