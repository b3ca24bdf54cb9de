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
    # fix after the first check: the handle's blade end is square (its R6 corners left sharp
    # notches where the 20 mm blade root met them), and the R1.5 point is a circle hulled with
    # the taper so the blade keeps its 110 mm (the W0405: a Fillet at the tip took 6.149 mm off)
    grip = RoundedRectangle(center=(handle_l / 2, 0), width=handle_l, height=24,
                            corner_radii=[6, 0, 0, 6])
    root = Polygon([(handle_l, 10), (handle_l + 80, 6)], mirror="x")
    point = Hull(Point(handle_l + 80, 6), Point(handle_l + 80, -6),
                 Circle(center=(handle_l + blade_l - 1.5, 0), radius=1.5))
    blade = Hull(root, point)

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
    assert self.bb.right - grip.bb.right == 110 mm, "blade 110 mm"
    assert root.bb.height == 20 mm, "blade 20 mm wide at its root"
    assert word.t.size == 10 mm, "MAIL 10 mm tall"
}
