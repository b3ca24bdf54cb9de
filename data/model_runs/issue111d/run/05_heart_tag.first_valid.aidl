# Heart gift tag (gifts): a heart 60 mm wide and 55 mm tall, 3 mm plywood: two round lobes of
# 32 mm diameter meeting in a V at the top, straight sides down to a point (rounded R1); a 5 mm
# ribbon hole in the left lobe, on its center line, 6 mm below the lobe's top; "FOR YOU" engraved
# 6 mm tall, centered left to right, its middle 6 mm below the lobes' centers, at most 34 mm wide.

thickness 3 mm

param lobe_d = 32 mm, min = 26 mm, max = 36 mm

solid tag {
    left_lobe = Circle(center=(-30 + lobe_d / 2, 0), diameter=lobe_d, construction=true)
    right_lobe = Circle(center=(30 - lobe_d / 2, 0), diameter=lobe_d, construction=true)
    tip = Circle(center=(0, lobe_d / 2 - 55 + 1), radius=1, construction=true)
    left_half = Hull(left_lobe, tip)
    right_half = Hull(right_lobe, tip)
    Fixed(left_lobe)
    Fixed(right_lobe)
    Fixed(tip)

    hole ribbon {
        c = Circle(center=(0, 0), diameter=5)
    }
    ribbon.c.center.x == left_lobe.center.x
    ribbon.c.center.y == left_lobe.bb.top - 6 mm

    drawing label {
        word = Text("FOR YOU", position=(0, -6), size=6, valign="middle", max_width=34)
    }
    label.bb.center_x == (left_lobe.center.x + right_lobe.center.x) / 2
    label.bb.center_y == left_lobe.center.y - 6 mm

    assert right_half.bb.right - left_half.bb.left == 60 mm, "60 mm wide"
    assert left_half.bb.top - left_half.bb.bottom == 55 mm, "55 mm tall"
    assert left_lobe.diameter == 32 mm, "32 mm lobes"
    assert ribbon.c.diameter == 5 mm, "5 mm ribbon hole"
    assert left_lobe.bb.top - ribbon.c.center.y == 6 mm, "ribbon hole 6 mm below the lobe's top"
    assert label.word.size <= 6 mm, "6 mm text"
    assert label.bb.width <= 34 mm, "text at most 34 mm wide"
}
