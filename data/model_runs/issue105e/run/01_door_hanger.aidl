# Door-hanger sign: a 90 x 220 mm rounded board (corner radius 8 mm), a 55 mm
# round hole for the door knob whose center is 45 mm below the top edge, a
# 4 mm wide slit from the hole to the right edge to slip it on, and the
# engraved words "DO NOT DISTURB" (size 10 mm, but never wider than 80 mm)
# centered 60 mm below the knob hole.

param w = 90 mm, min = 80 mm, max = 120 mm
param h = 220 mm, min = 180 mm, max = 260 mm
param knob_d = 55 mm, min = 40 mm, max = 65 mm

solid hanger {
    board = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=8)
    hole knob {
        c = Circle(center=(0, 60), diameter=knob_d)
    }
    hole slit {
        s = Rectangle(center=(30, 60), width=w / 2, height=4)
    }
    drawing words {
        t = Text("DO NOT DISTURB", position=(0, 0), size=10, valign="middle", max_width=80 mm)
    }
    AlignCenterX(knob, board)
    VerticalDistance(knob.c.center, board.top.midpoint, 45 mm)
    # slit: from the hole's center to the right edge, on the hole's axis
    AlignCenterY(slit, knob)
    slit.s.left.midpoint.x == knob.c.center.x
    AllowOverlap(knob, slit)  # the slit opens into the knob hole: one opening meant
    AlignCenterX(words, board)
    VerticalDistance(words.t.position, knob.c.center, 60 mm)

    assert words.bb.width <= 80 mm, "text fits 80 mm"
    assert board.bb.width == w and board.bb.height == h, "board size"
    assert board.bb.top - knob.c.center.y == 45 mm, "knob hole 45 mm below top"
}
