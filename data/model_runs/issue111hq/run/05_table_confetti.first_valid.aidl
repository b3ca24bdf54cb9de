# Request (parties): table confetti for Dad's 40th, cut from 3 mm gold mirror acrylic:
# sixteen 5-point stars 20 mm across (tips rounded 0.8 mm so they do not snap), sixteen
# hearts 18 mm wide, and five "40"s in bold, 16 mm tall, the two digits joined by a 2.5 mm
# bar along their feet so each "40" is one piece. Every piece is separate; laid out for the
# cutter in rows with at least 3 mm between pieces.

thickness 3 mm

def star_piece(x=0 mm, y=0 mm) -> solid {
    st = Star(center=(x, y), points=5, outer_radius=10, inner_radius=4.5, tip_radius=0.8)
}

def heart_piece(x=0 mm, y=0 mm) -> solid {
    left = Hull(Circle(center=(x - 4.3, y + 2.6), radius=4.7), Point(x, y - 8.5))
    right = Hull(Circle(center=(x + 4.3, y + 2.6), radius=4.7), Point(x, y - 8.5))
    Rigid(self)
}

def forty_piece(x=0 mm, y=0 mm) -> solid {
    word = Text("40", (x, y), size=16, font="sans:Bold")
    bar = Rectangle(center=(word.center.x, y + 1.25), width=word.bb.width, height=2.5)
}

assembly confetti {
    s = star_piece(x=0, y=0)
    stars = GridPattern(s, 2, 8, (24, 24))
    h = heart_piece(x=0, y=52)
    hearts = GridPattern(h, 2, 8, (24, 22))
    f = forty_piece(x=0, y=90)
    forties = GridPattern(f, 1, 5, (34, 0))

    assert len(stars) == 16 and len(hearts) == 16 and len(forties) == 5, "16 + 16 + 5 pieces"
    assert abs(stars[0].st.outer_radius * 2 - 20 mm) < 0.01 mm, "stars 20 mm across"
    assert abs(hearts[0].bb.width - 18 mm) < 0.2 mm, "hearts 18 mm wide"
    assert forties[0].word.size == 16 mm, "40s 16 mm tall"
    assert distance(stars[0], stars[1]) >= 3 mm and distance(stars[0], stars[8]) >= 3 mm,
        "3 mm between stars"
    assert distance(hearts[0], hearts[1]) >= 3 mm and distance(hearts[0], hearts[8]) >= 3 mm,
        "3 mm between hearts"
    assert distance(forties[0], forties[1]) >= 3 mm, "3 mm between 40s"
    assert distance(stars[8], hearts[0]) >= 3 mm and distance(hearts[8], forties[0]) >= 3 mm,
        "3 mm between the rows"
}
