# Crafts: a two-piece pom-pom maker of 3 mm MDF. Each piece is a C-shaped ring,
# 70 mm outside and 30 mm inside diameter, with an 8 mm wide opening cut from the
# centre hole straight out through the rim (to the right); every corner of the
# opening rounded 1.5 mm. Its size "70" is engraved 6 mm high, centred on the ring's
# band opposite the opening. The two pieces are cut side by side, 5 mm apart.
thickness 3 mm

param outer = 70 mm, min = 40 mm, max = 120 mm
param inner = 30 mm, min = 15 mm, max = 60 mm
param opening = 8 mm, min = 5 mm, max = 12 mm

def c_ring() -> solid {
    rim = Circle(center=(0, 0), diameter=outer)
    hole eye { c = Circle(center=(0, 0), diameter=inner) }
    hole gap { r = Rectangle(center=(outer / 4 + 5, 0), width=outer / 2 + 5, height=opening) }
    AllowOverlap(eye, gap)
    Concentric(eye.c, rim)
    AlignCenterY(gap, rim)
    gap.r.bb.left == rim.center.x
    drawing size { t = Text(f"{outer / 1 mm:.0f}", (-(outer + inner) / 4, 0), size=6, valign="middle") }
    size.t.position.x == rim.center.x - (outer + inner) / 4
    AlignCenterY(size, rim)
    Fillet(1.5)
}

assembly maker {
    a = c_ring()
    b = c_ring()
    b.rim.center.x == a.rim.center.x + outer + 5 mm
    AlignCenterY(b, a)

    assert a.rim.diameter == 70 mm and a.eye.c.diameter == 30 mm, "70 outside, 30 inside"
    assert a.gap.r.height == 8 mm, "8 mm opening"
    assert a.gap.r.bb.right - a.rim.center.x > 70 mm / 2, "the opening runs through the rim"
    assert b.rim.center.x - a.rim.center.x == 70 mm + 5 mm, "5 mm apart"
}
