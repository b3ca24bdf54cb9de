# Direction sign for a sports ground: an arrow-shaped board of 6 mm plywood, 260 mm
# long and 70 mm tall, square tail at the left, pointing right: the top and bottom
# edges run 225 mm, then meet at the tip on the centre line (a 35 mm long point).
# "PITCH 2" engraved 16 mm tall and "200 m" 10 mm tall under it, both centred on the
# 225 mm straight part, baselines 3 mm above and 19 mm below the centre line.
# An engraved border line following the outline 5 mm in.
# Two 5 mm screw holes for the post, 25 mm from the tail, 18 mm above and below the
# centre line, countersunk 10 mm.

units mm
thickness 6 mm

solid sign {
    board = Polygon([(260, 0), (225, 35), (0, 35)], mirror="x")

    drawing border {
        shape = Polygon([(260, 0), (225, 35), (0, 35)], mirror="x", construction=true)
        line = Inset(shape, 5)
    }
    AlignCenterY(border.shape, board)
    AlignLeft(border.shape, board)

    drawing words {
        name = Text("PITCH 2", (112.5, 3), size=16)
        dist = Text("200 m", (112.5, -19), size=10)
    }
    # centred on the straight part (x 0 to 225)
    words.name.position.x == board.bb.left + 225 / 2
    words.dist.position.x == board.bb.left + 225 / 2
    words.name.position.y == board.bb.center_y + 3
    words.dist.position.y == board.bb.center_y - 19

    hole post {
        c = Circle(center=(25, 18), diameter=5)
    }
    holes = LinearPattern(post, 2, (0, -36))
    post.c.center.x == board.bb.left + 25
    post.c.center.y == board.bb.center_y + 18
    Countersink(post, diameter=10)

    assert board.bb.width == 260 mm and board.bb.height == 70 mm, "260 x 70"
    assert board.points[1].x - board.bb.left == 225 mm, "225 mm straight edges"
    assert board.points[0].y == board.bb.center_y, "tip on the centre line"
    assert words.name.size == 16 mm and words.dist.size == 10 mm, "16 and 10 mm text"
    assert holes[0].c.center.y - holes[1].c.center.y == 36 mm, "18 above and below"
    assert holes[1].c.center.y == board.bb.center_y - 18 mm, "lower 18 below"
    assert holes[0].c.diameter == 5 mm, "5 mm screws"
    assert border.line.bb.width == 260 mm - 5 mm - 5 mm / sin(atan2(35, 35)), "border 5 in, tip included"
}
