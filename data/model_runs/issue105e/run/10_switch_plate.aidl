# Light-switch wall plate: a 70 x 115 mm plate with 3 mm rounded corners, a
# 10.5 x 24 mm rectangular opening for the toggle at its center, and two
# 3.5 mm countersunk screw holes (7 mm heads) on the vertical center line,
# 60.3 mm apart, centered on the opening.

param pw = 70 mm, min = 65 mm, max = 80 mm
param ph = 115 mm, min = 105 mm, max = 130 mm
param screw_pitch = 60.3 mm, min = 50 mm, max = 84 mm

solid wallplate {
    body = RoundedRectangle(center=(0, 0), width=pw, height=ph, corner_radius=3)
    hole toggle { r = Rectangle(center=(0, 0), width=10.5, height=24) }
    CenterInside(toggle, body)
    hole upper { c = Circle(center=(0, 30), diameter=3.5) }
    hole lower { c = Circle(center=(0, -30), diameter=3.5) }
    At(upper.c.center, toggle.r.center, dy=screw_pitch / 2)
    At(lower.c.center, toggle.r.center, dy=-screw_pitch / 2)
    Countersink([upper, lower], diameter=7 mm)

    assert upper.c.center.y - lower.c.center.y == 60.3 mm, "screws 60.3 mm apart"
    assert upper.bb.bottom > toggle.bb.top and lower.bb.top < toggle.bb.bottom, "screws clear of the opening"
}
