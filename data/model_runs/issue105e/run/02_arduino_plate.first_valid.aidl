# Arduino Uno mounting plate: a 90 x 70 mm plate with 4 mm rounded corners;
# the Uno's footprint (68.6 x 53.3 mm) centered on it; its four 3.2 mm mounting
# holes at the Uno's positions from the board's bottom-left corner:
# (14.0, 2.5), (15.3, 50.7), (66.1, 7.6), (66.1, 35.5) mm; and four 4 mm
# holes, 6 mm in from each plate corner, to screw the plate down.

param pw = 90 mm, min = 80 mm, max = 120 mm
param ph = 70 mm, min = 62 mm, max = 100 mm

solid plate {
    body = RoundedRectangle(center=(0, 0), width=pw, height=ph, corner_radius=4)
    uno = Rectangle(center=(0, 0), width=68.6, height=53.3, construction=true)
    CenterInside(uno, body)

    hole m1 { c = Circle(center=(-20, -24), diameter=3.2) }
    hole m2 { c = Circle(center=(-19, 24), diameter=3.2) }
    hole m3 { c = Circle(center=(32, -19), diameter=3.2) }
    hole m4 { c = Circle(center=(32, 9), diameter=3.2) }
    At(m1.c.center, uno.bottom_left, dx=14.0, dy=2.5)
    At(m2.c.center, uno.bottom_left, dx=15.3, dy=50.7)
    At(m3.c.center, uno.bottom_left, dx=66.1, dy=7.6)
    At(m4.c.center, uno.bottom_left, dx=66.1, dy=35.5)

    hole corner { c = Circle(center=(-39, -29), diameter=4) }
    CornerPattern(corner, body, inset=6)

    assert body.bb.width == pw and body.bb.height == ph, "plate size"
    assert m4.c.center.y - m3.c.center.y == 27.9 mm, "Uno right holes 27.9 mm apart"
    assert m2.c.center.y - m1.c.center.y == 48.2 mm, "Uno left holes 48.2 mm apart"
}
