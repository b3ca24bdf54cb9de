# Request: a nailing template for a string-art heart, cut from 3 mm MDF. A 250 x 250 mm
# plate (6 mm corners) laid on the 18 mm pine board and pinned through four 4 mm holes 12 mm
# in from each corner. The heart: two round lobes of 50 mm radius whose centres are 80 mm
# apart, 30 mm above the heart's middle line, and a point 100 mm below that line; 48 holes of
# 2 mm on its outline (a nail is tapped through each), evenly spread: one at the dip, one at
# the point, 13 more on each lobe and 10 on each straight side. Each hole numbered 1-48
# counter-clockwise from the dip, 3.5 mm engraved numbers 7 mm outside the outline. Title
# "HEART - 48 NAILS" engraved 5 mm tall, 12 mm above the bottom edge.

thickness 3 mm

R = 50 mm                  # lobe radius
lobe_x = 40 mm             # lobe centres at x = -40 and 40
lobe_y = 30 mm
tip_y = -100 mm
nails = 48
arc_n = 13                 # nails on each lobe after the dip
line_n = 11                # intervals on each straight side (10 nails between)

dip_y = lobe_y + sqrt(R ** 2 - lobe_x ** 2)
dip_ang = atan2(dip_y - lobe_y, lobe_x)                 # the dip on the left lobe
to_tip = atan2(tip_y - lobe_y, lobe_x)                  # left lobe centre towards the tip
tan_ang = to_tip - acos(R / sqrt(lobe_x ** 2 + (tip_y - lobe_y) ** 2))   # tangent point
arc_step = (tan_ang + 360 deg - dip_ang) / arc_n
tx = -lobe_x + R * cos(tan_ang)
ty = lobe_y + R * sin(tan_ang)

# hole k on the left half: 1..13 on the lobe, 14..23 down the straight side
def side_x(k) = (-lobe_x + R * cos(dip_ang + k * arc_step)) if k <= arc_n else (tx + (0 - tx) * (k - arc_n) / line_n)
def side_y(k) = (lobe_y + R * sin(dip_ang + k * arc_step)) if k <= arc_n else (ty + (tip_y - ty) * (k - arc_n) / line_n)
# hole i, 0..47, counter-clockwise from the dip
def hx(i) = 0 mm if i == 0 else (side_x(i) if i < 24 else (0 mm if i == 24 else -side_x(48 - i)))
def hy(i) = dip_y if i == 0 else (side_y(i) if i < 24 else (tip_y if i == 24 else side_y(48 - i)))
def out(i) = sqrt(hx(i) ** 2 + (hy(i) + 10 mm) ** 2)
def lx(i) = hx(i) + 7 mm * hx(i) / out(i)
def ly(i) = hy(i) + 7 mm * (hy(i) + 10 mm) / out(i)
def gap(i) = sqrt((hx((i + 1) % nails) - hx(i)) ** 2 + (hy((i + 1) % nails) - hy(i)) ** 2)

solid template {
    plate = RoundedRectangle(center=(0, -10 mm), width=250 mm, height=250 mm, corner_radius=6 mm)

    for i in range(nails) {
        hole nail { c = Circle(center=(hx(i), hy(i)), diameter=2 mm) }
    }
    for p in [(-1, -1), (1, -1), (-1, 1), (1, 1)] {
        hole pin { c = Circle(center=(p[0] * (125 mm - 12 mm), -10 mm + p[1] * (125 mm - 12 mm)),
                              diameter=4 mm) }
    }

    drawing numbers {
        for i in range(nails) {
            n = Text(str(i + 1), position=(lx(i), ly(i)), size=3.5 mm, valign="middle")
        }
    }
    drawing title {
        words = Text("HEART - 48 NAILS", position=(0, -135 mm + 12 mm), size=5 mm)
    }

    assert len(nail) == 48, "48 nails"
    assert plate.width == 250 mm and plate.height == 250 mm, "250 x 250 plate"
    assert min([gap(i) for i in range(nails)]) >= 10 mm, "nails at least 10 mm apart"
    assert max([gap(i) for i in range(nails)]) <= 13 mm, "nails at most 13 mm apart"
    assert title.words.position.y - plate.bb.bottom == 12 mm, "title 12 mm above the bottom"
    assert hy(24) - lobe_y == -130 mm, "point 100 mm below the middle line"
}
