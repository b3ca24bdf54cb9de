# Request: a "hot surface" warning sign for the kiln room, cut from 3 mm yellow-on-black
# engraving laminate (what is engraved shows black). Plate 160 x 210 mm portrait, corners
# R6, screwed to the wall by two M4 countersunk screws (holes 10 mm in from the sides and
# 10 mm below the top, 8 mm countersinks). The ISO-style warning triangle: equilateral,
# 120 mm on a side to its sharp corners, corners rounded R4, its base 15 mm below the
# plate's centre, a filled border band 8 mm wide. Inside it the hot-surface symbol, filled:
# a 60 x 5 mm bar centred 0 mm (on the plate's centre line, y = 0) and, above it, three
# wavy heat lines 4 mm wide, 11 mm apart, rising from 8 mm to 38 mm above the centre, each
# swinging 3 mm either side with a 20 mm wavelength. Below: "CAUTION" (16 mm) and
# "HOT SURFACE" (13 mm, no wider than 140 mm), filled bold, centred 45 mm and 78 mm below
# the plate's centre.

import "std/fasteners.aidl"

thickness 3 mm

param plate_w = 160 mm
param plate_h = 210 mm
param side = 120 mm
param corner = 4 mm
param band = 8 mm
param base_y = -15 mm

core_side = side - 2 * sqrt(3) * corner
core_h = core_side * sqrt(3) / 2

solid sign {
    plate = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=6)
    Fixed(plate)

    left_hole = clearance_hole(size=4, cx=-plate_w / 2 + 10 mm, cy=plate_h / 2 - 10 mm)
    right_hole = clearance_hole(size=4, cx=plate_w / 2 - 10 mm, cy=plate_h / 2 - 10 mm)
    Countersink([left_hole, right_hole], diameter=8)

    drawing warning {
        core = Triangle(center=(0, base_y + corner + core_h / 2), base=core_side, height=core_h,
                        construction=true)
        outer = Offset(core, corner, construction=true)
        border = Shell(outer, -band, fill=true)
        bar = Rectangle(center=(0, 0), width=60, height=5, fill=true)
        for i in range(3) {
            wave = Spline([((i - 1) * 11 mm + 3 mm * sin(j * 90 deg), 8 mm + j * 5 mm)
                           for j in range(7)])
            heat = Stroke(wave, width=4, fill=true)
        }
    }
    drawing words {
        caution = Text("CAUTION", position=(0, -45), size=16, font="sans:Bold",
                       valign="middle", fill=true)
        hot = Text("HOT SURFACE", position=(0, -78), size=13, font="sans:Bold",
                   valign="middle", max_width=140, fill=true)
    }

    # the request's numbers
    assert plate.width == 160 mm and plate.height == 210 mm, "plate 160 x 210"
    assert left_hole.c.center.x - plate.bb.left == 10 mm, "holes 10 in from the sides"
    assert plate.bb.top - left_hole.c.center.y == 10 mm, "holes 10 below the top"
    assert plate.bb.right - right_hole.c.center.x == 10 mm, "right hole 10 in"
    assert core_side + 2 * sqrt(3) * corner == 120 mm, "triangle 120 to its sharp corners"
    assert warning.core.a.y - corner - plate.center.y == -15 mm, "base 15 below the centre"
    assert warning.bar.width == 60 mm and warning.bar.height == 5 mm, "bar 60 x 5"
    assert warning.bar.center.y == plate.center.y, "bar on the centre line"
    assert len(warning.heat) == 3, "three heat lines"
    assert warning.wave[2].points[0].x - warning.wave[1].points[0].x == 11 mm, "11 apart"
    assert warning.wave[0].points[0].y == 8 mm and warning.wave[0].points[6].y == 38 mm,
           "from 8 to 38 above the centre"
    assert words.caution.position.y == -45 mm and words.hot.position.y == -78 mm, "text rows"
    assert words.hot.bb.width <= 140 mm, "HOT SURFACE no wider than 140"
    # clearances a sign-maker checks
    assert distance(warning.heat[0], warning.border) >= 2 mm, "heat lines clear of the border"
    assert distance(warning.heat[2], warning.border) >= 2 mm, "heat lines clear of the border"
    assert distance(warning.bar, warning.border) >= 2 mm, "bar clear of the border"
    assert distance(warning.border, left_hole) >= 3 mm, "border clear of the screws"
    assert distance(words.caution, warning.border) >= 3 mm, "CAUTION clear of the triangle"
    assert words.hot.bb.bottom - plate.bb.bottom >= 10 mm, "margin under the text"
}
