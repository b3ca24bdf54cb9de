# Request (garden): cabbage root-fly collars for my brassica seedlings, cut from 2 mm
# greyboard. Six collars on one sheet, 3 across and 2 down, 4 mm apart. Each collar is a
# 100 mm disc with a 5 mm stem hole in the middle, a slit from the rim straight down to the
# stem hole (so it slips round the stem), and a star of 6 slits, each from the stem hole out
# to 10 mm from the centre, so the hole gives as the stem grows; none of them may fall on the
# rim slit. Each collar engraved with its number 1-6 (plain strokes, 8 mm tall), centred
# 30 mm above the middle, so I can tell which plant has had its collar checked.

thickness 2 mm

n_collars = 6
disc_d = 100 mm
stem_d = 5 mm
star_r = 10 mm
gap = 4 mm

def collar(n=1) -> solid {
    disc = Circle(center=(0, 0), diameter=disc_d)
    hole stem { c = Circle(center=(0, 0), diameter=stem_d) }
    cut slits {
        entry = Line((0, -disc_d / 2), (0, -stem_d / 2))
        for k in range(6) {
            s = Line((stem_d / 2 * cos(k * 60 deg), stem_d / 2 * sin(k * 60 deg)),
                     (star_r * cos(k * 60 deg), star_r * sin(k * 60 deg)))
        }
    }
    drawing number { t = Text(str(n), position=(0, 30), size=8, valign="middle") }
}

assembly collars {
    for i in range(n_collars) {
        c = collar(n=i + 1)
    }
    for i in range(1, n_collars) {
        if i % 3 == 0 {
            Below(c[i], c[i - 3], gap=gap)
            AlignLeft(c[i], c[i - 3])
        } else {
            RightOf(c[i], c[i - 1], gap=gap)
            AlignTop(c[i], c[i - 1])
        }
    }

    # the request's numbers
    assert len(c) == 6, "six collars"
    assert c[0].disc.diameter == 100 mm, "100 mm discs"
    assert c[1].bb.left - c[0].bb.right == 4 mm, "4 mm apart across"
    assert c[0].bb.bottom - c[3].bb.top == 4 mm, "4 mm apart down"
    assert c[0].number.t.position.y - c[0].disc.center.y == 30 mm, "number 30 above the middle"
    assert distance(c[0].number, c[0].slits) >= 5 mm, "number clear of the slits"
}
