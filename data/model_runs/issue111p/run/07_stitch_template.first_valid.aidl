# Crafts: leather stitching template, 2 mm acrylic strip 200 x 40 mm, its top-right corner
# rounded R20 (the others R3). Stitch holes 1.5 mm: a straight row 4 mm above the bottom edge
# at 4 mm pitch from 8 mm to 192 mm (47 holes), and 7 holes on the R20 corner's stitch arc
# (4 mm in: R16 about the corner's centre) every 15 deg from 0 to 90 deg. Engraved ruler ticks
# on the top edge every 10 mm from 10 to 170 mm (5 mm long, 8 mm every 50), and
# "STITCH 4 mm" 5 mm strokes in the middle.

thickness 2 mm

solid template {
    strip = RoundedRectangle(bottom_left=(0, 0), width=200, height=40, corner_radii=[3, 20, 3, 3])
    hole row {
        for i in range(47) {
            h = Circle(center=(8 + 4 * i, 4), diameter=1.5)
        }
    }
    hole corner {
        for k in range(7) {
            h = Circle(center=(180 + 16 * cos(k * 15 deg), 20 + 16 * sin(k * 15 deg)), diameter=1.5)
        }
    }
    drawing marks {
        for j in range(17) {
            tick = Line((10 + 10 * j, 40), (10 + 10 * j, 40 - (8 if (j + 1) % 5 == 0 else 5)))
        }
        label = Text("STITCH 4 mm", (90, 20), size=5, valign="middle")
    }

    assert strip.width == 200 mm and strip.height == 40 mm, "200 x 40 strip"
    assert len(row.h) == 47, "47 holes in the row"
    assert row.h[1].center.x - row.h[0].center.x == 4 mm, "4 mm pitch"
    assert row.h[46].center.x == 192 mm, "row ends at 192"
    assert len(corner.h) == 7, "7 holes on the corner"
    assert row.h[0].diameter == 1.5 mm, "1.5 mm holes"
}
