# Office: a letter opener from 3 mm acrylic, 200 mm long overall.
# Handle 90 x 24 mm, corners R6; a 5 mm hanging hole centred 8 mm from the handle's end.
# Blade 110 mm long from the handle's end: 20 mm wide at its root, 12 mm wide 80 mm along,
# then tapering to a point on the axis, the point rounded R1.5.
# "MAIL" cut through the handle as a stencil in sans Bold, 10 mm tall, its middle on the
# axis, centred 50 mm from the handle's end.

units mm
thickness 3 mm

param handle_l = 90 mm, min = 70 mm, max = 110 mm
param blade_l = 110 mm, min = 80 mm, max = 140 mm

solid opener {
    grip = RoundedRectangle(center=(handle_l / 2, 0), width=handle_l, height=24, corner_radius=6)
    blade = Polygon([(handle_l, 10), (handle_l + 80, 6), (handle_l + blade_l, 0)], mirror="x")
    RightOf(blade, grip)
    AlignCenterY(blade, grip)
    Fillet(blade.points[2], 1.5)

    hole hang {
        c = Circle(center=(8, 0), diameter=5)
    }
    HorizontalDistance(grip.left.midpoint, hang.c.center, 8)
    AlignCenterY(hang, grip)

    hole word {
        t = Text("MAIL", position=(50, 0), size=10, font="sans:Bold", valign="middle", stencil=true)
    }
    HorizontalDistance(grip.left.midpoint, word.t.position, 50)
    VerticalDistance(grip.center, word.t.position, 0)

    assert self.bb.width == 200 mm, "200 mm long overall"
    assert grip.bb.width == 90 mm and grip.bb.height == 24 mm, "handle 90 x 24"
    assert blade.bb.width == 110 mm, "blade 110 mm"
    assert blade.bb.height == 20 mm, "blade 20 mm wide at its root"
    assert word.t.size == 10 mm, "MAIL 10 mm tall"
}
