# Music: a fret-slotting template for a 500 mm scale (cigar-box guitar), frets 1 to 12.
# Strip 280 x 50 mm, corner radius 3 mm, 3 mm acrylic. The nut line 10 mm from the left
# end; fret n at 500 * (1 - 2^(-n/12)) mm from the nut (fret 12 at 250 mm). Every line
# (nut and 12 frets) is a marking slit 1 mm wide and 20 mm long, from 4 to 24 mm above the
# bottom edge. Above each slit its number engraved 4 mm tall ("NUT" for the nut), baseline
# 28 mm above the bottom. "SCALE 500 MM" engraved 5 mm tall, centred, baseline 40 mm above the
# bottom. A 5 mm hanging hole 8 mm from the right end, centred in height.

thickness 3 mm

param scale = 500 mm, min = 300 mm, max = 520 mm
nut_x = 10 mm
frets = 12

solid template {
    body = RoundedRectangle(bottom_left=(0, 0), width=280, height=50, corner_radius=3)

    hole slits {
        for i in range(frets + 1) {
            s = Rectangle(center=(nut_x + scale * (1 - 2 ** (-i / 12)), 14), width=1, height=20)
        }
    }

    drawing numbers {
        for i in range(frets + 1) {
            n = Text("NUT" if i == 0 else str(i), (nut_x + scale * (1 - 2 ** (-i / 12)), 28),
                     size=4)
        }
        title = Text("SCALE 500 MM", (140, 40), size=5)
    }

    hole hang {
        c = Circle(center=(272, 25), diameter=5)
    }

    assert body.width == 280 mm and body.height == 50 mm, "strip 280 x 50"
    assert len(slits.s) == 13, "nut and 12 frets"
    assert slits.s[0].center.x - body.bb.left == 10 mm, "nut 10 mm from the left end"
    assert abs(slits.s[12].center.x - slits.s[0].center.x - 250 mm) < 0.001 mm, "fret 12 at 250 mm"
    assert abs(slits.s[1].center.x - slits.s[0].center.x - 28.063 mm) < 0.01 mm, "fret 1 at 28.06 mm"
    assert slits.s[5].width == 1 mm and slits.s[5].height == 20 mm, "slits 1 x 20"
    assert slits.s[5].bb.bottom - body.bb.bottom == 4 mm, "slits from 4 mm above the bottom"
    assert slits.s[5].bb.top - body.bb.bottom == 24 mm, "to 24 mm"
    assert numbers.n[3].size == 4 mm and numbers.title.size == 5 mm, "text sizes"
    assert numbers.bb.top < body.bb.top - 2 mm, "text inside the strip"
    assert hang.c.diameter == 5 mm, "5 mm hanging hole"
    assert body.bb.right - hang.c.center.x == 8 mm, "8 mm from the right end"
    assert hang.bb.left > slits.s[12].bb.right + 3 mm, "hole clear of fret 12"
}
