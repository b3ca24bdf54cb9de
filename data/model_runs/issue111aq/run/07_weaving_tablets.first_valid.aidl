# Request (crafts): a starter set of four tablets (cards) for tablet weaving, 1.5 mm ply.
# Each is 55 mm square with R6 corners and four 7 mm holes, each centred 10 mm in from the
# two nearest edges. The holes are lettered A, B, C, D clockwise from the top-left (A
# top-left, B top-right, C bottom-right, D bottom-left): engraved letters 5 mm tall, each
# centred 9 mm from its hole's centre towards the card's centre (6.36 mm in x and in y).
# The card's number (1 to 4) is engraved 8 mm tall in the middle.

thickness 1.5 mm

LETTERS = ["D", "C", "B", "A"]          # in CornerPattern's order: BL, BR, TR, TL
TOWARD_X = [1, -1, -1, 1]
TOWARD_Y = [1, 1, -1, -1]
step = 9 mm / sqrt(2)

def tablet(n=1) -> solid {
    body = RoundedRectangle(center=(0, 0), width=55, height=55, corner_radius=6)
    hole h { c = Circle(center=(0, 0), diameter=7) }
    hs = CornerPattern(h, body, inset=10)
    drawing marks {
        for i in range(4) {
            t = Text(LETTERS[i], position=(0, 0), size=5, valign="middle")
        }
        num = Text(str(n), position=(0, 0), size=8, valign="middle")
    }
    for i in range(4) {
        At(marks.t[i].position, hs[i].c.center, dx=TOWARD_X[i] * step, dy=TOWARD_Y[i] * step)
    }
    At(marks.num.position, body.center)
    assert body.width == 55 mm and body.height == 55 mm, "55 mm square"
    assert hs[3].c.center.x - body.bb.left == 10 mm and body.bb.top - hs[3].c.center.y == 10 mm,
        "holes 10 mm in from the edges"
    assert len(hs) == 4, "four holes"
    assert marks.t[3].text == "A" and marks.t[3].position.x < body.center.x and marks.t[3].position.y > body.center.y,
        "A is top-left"
    assert marks.t[2].text == "B" and marks.t[2].position.x > body.center.x and marks.t[2].position.y > body.center.y,
        "B is top-right"
}

assembly tablets {
    for k in range(4) {
        card = tablet(n=k + 1)
        card.bb.center_x == k * 62 mm
        card.bb.center_y == 0 mm
    }
    assert len(card) == 4, "four tablets"
}
