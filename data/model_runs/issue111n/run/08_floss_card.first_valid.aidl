# Crafts: an embroidery-floss organiser card, 2 mm board, 150 x 110 mm, corners R5.
# A grid of 4 rows x 5 columns of 12 mm holes to loop skeins through, columns 24 mm
# apart and rows 22 mm apart; the top row's centres 27 mm below the top edge; the
# grid centred left-right on x = 8 mm right of the card's centre (clear of the binder
# holes). Under each hole its number 1 to 20 (row by row, left to right) engraved in
# stroke text 3 mm high, baseline 10.5 mm below the hole's centre. Two 6 mm ring-binder
# holes, 8 mm in from the left edge, 80 mm apart, centred top to bottom. "FLOSS"
# engraved 6 mm high over the grid, its top 6 mm below the top edge.

units mm
thickness 2 mm

rows = 4
cols = 5
dx = 24 mm
dy = 22 mm

solid card {
    body = RoundedRectangle(center=(0, 0), width=150, height=110, corner_radius=5)

    hole skein {
        c = Circle(center=(8 - 2 * dx, 28), diameter=12)
    }
    skeins = GridPattern(skein, rows, cols, (dx, -dy))

    drawing numbers {
        for r in range(rows) {
            for c in range(cols) {
                n = Text(str(r * cols + c + 1), (8 - 2 * dx + c * dx, 28 - r * dy - 10.5), size=3)
            }
        }
    }

    hole binder {
        top = Circle(center=(-67, 40), diameter=6)
        low = Circle(center=(-67, -40), diameter=6)
    }

    drawing title {
        word = Text("FLOSS", (8, 43), size=6)
    }

    # the request's numbers
    assert body.width == 150 mm and body.height == 110 mm, "card 150 x 110"
    assert len(skeins) == 20, "4 x 5 holes"
    assert skein.c.diameter == 12 mm, "12 mm holes"
    assert body.bb.top - skein.c.center.y == 27 mm, "top row 27 below the top edge"
    assert skein.c.center.x + 2 * dx == body.center.x + 8 mm, "grid centred 8 right of centre"
    assert numbers.n[0][0].size == 3 mm, "3 mm numbers"
    assert skein.c.center.y - numbers.n[0][0].position.y == 10.5 mm, "numbers 10.5 below the holes"
    assert numbers.n[0][0].position.x == skein.c.center.x, "number under its hole"
    assert numbers.n[0][0].bb.top < skein.c.bb.bottom - 1 mm, "number clear of its hole"
    assert numbers.n[3][4].bb.bottom > body.bb.bottom + 3 mm, "last numbers on the card"
    assert skeins[19].bb.right < body.bb.right - 5 mm, "grid inside the card"
    assert binder.top.diameter == 6 mm, "6 mm binder holes"
    assert binder.top.center.y - binder.low.center.y == 80 mm, "80 mm apart"
    assert binder.top.center.x - body.bb.left == 8 mm, "8 in from the left"
    assert binder.top.center.y + binder.low.center.y == 2 * body.center.y, "centred top to bottom"
    assert title.word.size == 6 mm, "title 6 mm"
    assert body.bb.top - title.bb.top == 6 mm, "title's top 6 below the top edge"
    assert title.bb.bottom > skein.c.bb.top + 3 mm, "title clear of the holes"
}
