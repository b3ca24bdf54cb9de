# Tea-light lantern side panel, 3 mm plywood: a 100 x 100 mm rectangle topped by a half circle
# of radius 50 mm (150 mm tall overall). Star-shaped openings (five points, outer radius 8 mm,
# inner 3.5 mm, a tip up) in 3 columns x 4 rows at 25 mm pitch, columns at x = -25, 0, +25 mm
# from the panel's center line, rows 20, 45, 70 and 95 mm above the bottom edge; one large star
# opening (outer 14 mm, inner 6 mm) centered in the arch, 125 mm above the bottom edge. Two
# tabs 15 x 3 mm below the bottom edge, centered 30 mm left and right of the center line.

units mm
thickness 3 mm

solid panel {
    body = Rectangle(bottom_left=(-50, 0), width=100, height=100)
    arch = Sector(center=(0, 100), radius=50, start_angle=0 deg, end_angle=180 deg)
    tab_l = Rectangle(center=(-30, -1.5), width=15, height=3)
    tab_r = Rectangle(center=(30, -1.5), width=15, height=3)

    hole star {
        s = Star(center=(-25, 20), points=5, outer_radius=8, inner_radius=3.5)
    }
    stars = GridPattern(star, 4, 3, 25 mm)

    hole big_star {
        s = Star(center=(0, 125), points=5, outer_radius=14, inner_radius=6)
    }

    assert abs(body.bb.width - 100 mm) < 0.001 mm, "100 mm wide"
    assert abs(arch.bb.top - body.bb.bottom - 150 mm) < 0.001 mm, "150 mm tall"
    assert len(stars) == 12, "3 x 4 stars"
    assert abs(stars[11].s.center.y - body.bb.bottom - 95 mm) < 0.001 mm, "top row 95 mm up"
    assert abs(stars[11].s.center.x - 25 mm) < 0.001 mm, "right column at +25 mm"
    assert abs(big_star.s.center.y - body.bb.bottom - 125 mm) < 0.001 mm, "big star 125 mm up"
    assert abs(tab_r.bb.width - 15 mm) < 0.001 mm and abs(tab_r.bb.height - 3 mm) < 0.001 mm, "tabs 15 x 3"
}
