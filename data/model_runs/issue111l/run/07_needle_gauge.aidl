# Crafts: knitting-needle gauge, 3 mm acrylic: a 130 x 80 mm card with 6 mm corner radii;
# twelve gauge holes in two rows of six, 18 mm apart, centred across: top row 2.0, 2.5,
# 3.0, 3.5, 4.0, 4.5 mm at 18 mm above the centre, bottom row 5.0, 5.5, 6.0, 7.0, 8.0,
# 9.0 mm at 15 mm below it; each size engraved 4 mm tall under its hole (baseline 10 mm
# under the top row's centres, 12 mm under the bottom row's); "NEEDLE GAUGE" engraved
# 6 mm tall, centred, baseline 9 mm below the top edge; a 6 mm hanging hole 10 mm in from
# the left and top edges.

thickness 3 mm
top_sizes = [2.0, 2.5, 3.0, 3.5, 4.0, 4.5]
bottom_sizes = [5.0, 5.5, 6.0, 7.0, 8.0, 9.0]

solid gauge {
    card = RoundedRectangle(center=(0, 0), width=130, height=80, corner_radius=6)

    hole upper {
        for i in range(6) {
            h = Circle(center=(-45 + i * 18, 18), diameter=top_sizes[i])
        }
    }
    hole lower {
        for i in range(6) {
            h = Circle(center=(-45 + i * 18, -15), diameter=bottom_sizes[i])
        }
    }
    drawing sizes {
        for i in range(6) {
            t = Text(f"{top_sizes[i]:.1f}", (-45 + i * 18, 8), size=4)
        }
        for i in range(6) {
            b = Text(f"{bottom_sizes[i]:.1f}", (-45 + i * 18, -27), size=4)
        }
    }
    drawing title {
        word = Text("NEEDLE GAUGE", (0, 31), size=6)
    }
    hole hang { c = Circle(center=(-55, 30), diameter=6) }

    assert card.width == 130 mm and card.height == 80 mm, "130 x 80"
    assert len(upper.h) == 6 and len(lower.h) == 6, "two rows of six"
    assert upper.h[0].diameter == 2 mm and upper.h[5].diameter == 4.5 mm, "top row 2.0 to 4.5"
    assert lower.h[0].diameter == 5 mm and lower.h[5].diameter == 9 mm, "bottom row 5.0 to 9.0"
    assert upper.h[1].center.x - upper.h[0].center.x == 18 mm, "18 apart"
    assert (upper.h[0].center.x + upper.h[5].center.x) / 2 == card.center.x, "centred"
    assert upper.h[0].center.y - card.center.y == 18 mm, "top row 18 up"
    assert card.center.y - lower.h[0].center.y == 15 mm, "bottom row 15 down"
    assert upper.h[0].center.y - sizes.t[0].position.y == 10 mm, "top labels 10 under"
    assert lower.h[0].center.y - sizes.b[0].position.y == 12 mm, "bottom labels 12 under"
    assert sizes.t[0].size == 4 mm, "4 mm labels"
    assert sizes.b[5].bb.top < lower.h[5].bb.bottom, "labels clear of the holes"
    assert sizes.t[5].bb.top < upper.h[5].bb.bottom, "labels clear of the holes"
    assert sizes.bb.bottom > card.bb.bottom, "labels on the card"
    assert title.word.size == 6 mm, "6 mm title"
    assert card.bb.top - title.word.position.y == 9 mm, "title 9 below the top"
    assert title.bb.center_x == card.center.x or abs(title.word.position.x - card.center.x) < 0.001 mm, "title centred"
    assert hang.c.diameter == 6 mm, "6 mm hanging hole"
    assert hang.c.center.x - card.bb.left == 10 mm and card.bb.top - hang.c.center.y == 10 mm, "10 in"
    assert hang.bb.right < title.bb.left, "hanging hole clear of the title"
}
