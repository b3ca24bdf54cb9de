# Toys: a button whirligig (spun on a looped string). A saw-tooth disc: 24 teeth, tips on a
# 70 mm circle (R35), notches at R32. Two 3 mm string holes 8 mm apart (centre to centre),
# side by side across the centre. Three curved windows for the look when it spins: arc slots
# 5 mm wide on a 22 mm radius, each spanning 80 degrees, 120 degrees apart, the first from
# 10 to 90 degrees. 3 mm plywood.

thickness 3 mm

solid whirligig {
    disc = Star(center=(0, 0), points=24, outer_radius=35, inner_radius=32)

    hole strings {
        left = Circle(center=(-4, 0), diameter=3)
        right = Circle(center=(4, 0), diameter=3)
    }
    CenterInside(strings, disc)

    hole window {
        w = ArcSlot(center=(0, 0), radius=22, start_angle=10 deg, end_angle=90 deg, width=5)
    }
    Concentric(window.w, disc)
    windows = CircularPattern(window, 3, disc.center)

    assert disc.outer_radius == 35 mm and disc.inner_radius == 32 mm, "tips R35, notches R32"
    assert len(disc.points) == 48, "24 teeth"
    assert whirligig.bb.width <= 70 mm, "70 mm across the tips"
    assert strings.right.center.x - strings.left.center.x == 8 mm, "string holes 8 mm apart"
    assert strings.left.diameter == 3 mm, "3 mm string holes"
    assert len(windows) == 3, "three windows"
    assert window.w.radius == 22 mm and window.w.width == 5 mm, "R22, 5 mm wide"
    assert strings.bb.right < window.w.radius - 2.5 mm - 2 mm, "string holes clear of the windows"
}
