# Log-scale rule (science: a slide rule's D scale beside its L scale): a 280 x 36 mm bar of
# 3 mm acrylic, corners R3. Along the top edge the D scale, 250 mm long, its "1" 15 mm from the
# left end: a tick at each of 1, 2, ..., 10 at 250 mm x log10(n) (so 2 at 75.26 mm, 3 at
# 119.28 mm), 8 mm long down from the top edge, numbered 4 mm high (baseline 14 mm below the
# top); a 5 mm tick at each of 1.5, 2.5, ..., 9.5. Along the bottom edge the L scale over the
# same 250 mm: ticks at 0, 0.1, ..., 1.0 every 25 mm, 8 mm long up from the bottom edge,
# numbered 3 mm high with one decimal (baseline 11 mm above the bottom); 5 mm ticks halfway.
# "D" and "L" engraved 5 mm high, 6 mm from the left end, level with the scales' numbers.
units mm
thickness 3 mm

L = 250 mm
x0 = 15 mm
# log10 of 1..10 and of 1.5..9.5 (the language has no log function)
LOG_N = [0, 0.30103, 0.47712, 0.60206, 0.69897, 0.77815, 0.84510, 0.90309, 0.95424, 1]
LOG_HALF = [0.17609, 0.39794, 0.54407, 0.65321, 0.74036, 0.81291, 0.87506, 0.92942, 0.97772]

solid rule {
    body = RoundedRectangle(bottom_left=(0, 0), width=280, height=36, corner_radius=3)

    drawing d_scale {
        for i in range(10) {
            major = Line((x0 + L * LOG_N[i], 36), (x0 + L * LOG_N[i], 28))
            num = Text(str(i + 1), (x0 + L * LOG_N[i], 36 - 14), size=4)
        }
        for i in range(9) {
            minor = Line((x0 + L * LOG_HALF[i], 36), (x0 + L * LOG_HALF[i], 31))
        }
        name = Text("D", (6, 36 - 14), size=5, anchor="start")
    }

    drawing l_scale {
        for i in range(11) {
            major = Line((x0 + i * L / 10, 0), (x0 + i * L / 10, 8))
            num = Text(f"{i / 10:.1f}", (x0 + i * L / 10, 11), size=3)
        }
        for i in range(10) {
            minor = Line((x0 + (i + 0.5) * L / 10, 0), (x0 + (i + 0.5) * L / 10, 5))
        }
        name = Text("L", (6, 11), size=5, anchor="start")
    }

    assert body.bb.width == 280 mm and body.bb.height == 36 mm, "bar 280 x 36"
    assert d_scale.major[0].start.x - body.bb.left == 15 mm, "D's 1 at 15 mm"
    assert abs(d_scale.major[1].start.x - d_scale.major[0].start.x - 75.26 mm) < 0.01 mm, "2 at 75.26"
    assert abs(d_scale.major[2].start.x - d_scale.major[0].start.x - 119.28 mm) < 0.01 mm, "3 at 119.28"
    assert d_scale.major[9].start.x - d_scale.major[0].start.x == 250 mm, "D scale 250 long"
    assert l_scale.major[10].start.x - l_scale.major[0].start.x == 250 mm, "L scale 250 long"
    assert len(d_scale.minor) == 9 and len(l_scale.minor) == 10, "half ticks"
}
