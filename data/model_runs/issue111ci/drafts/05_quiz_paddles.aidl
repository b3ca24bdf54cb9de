# Request: answer paddles for a pub-quiz party night, 4 mm birch ply, one each for A, B, C
# and D. Each paddle: a 120 mm round head with its letter cut right through as a 70 mm bold
# stencil (counters held by bridges), so it reads from across the room; a 25 mm wide handle
# running 130 mm below the head (its end fully rounded) with a 6 mm hole 12.5 mm from the end
# to hang the set on a hook; the neck rounded into the head with 10 mm fillets; "QUIZ"
# engraved along the handle, 8 mm letters, reading bottom to top. Laid out 140 mm apart.

thickness 4 mm

letters = ["A", "B", "C", "D"]
head_d = 120 mm
handle_w = 25 mm
handle_len = 130 mm
pitch = 140 mm

def paddle(letter, x0) -> solid {
    head = Circle(center=(x0, 0), diameter=head_d)
    grip = RoundedRectangle(bottom_left=(x0 - handle_w / 2, -head_d / 2 - handle_len),
                            width=handle_w, height=handle_len + 10 mm,
                            corner_radii=[0, 0, handle_w / 2, handle_w / 2])
    Fillet([head, grip], 10)
    hole mark {
        l = Text(letter, position=(x0, 0), size=70, font="sans:Bold", valign="middle",
                 stencil=true)
    }
    hole hang {
        c = Circle(center=(x0, -head_d / 2 - handle_len + handle_w / 2), diameter=6)
    }
    drawing tag {
        t = Text("QUIZ", position=(x0, -head_d / 2 - 65 mm), size=8, rotation=90 deg,
                 valign="middle")
    }
}

assembly quiz {
    for i in range(4) {
        p = paddle(letter=letters[i], x0=i * pitch)
    }

    assert len(p) == 4, "four paddles, A to D"
    assert p[0].head.diameter == 120 mm, "120 mm heads"
    assert p[0].head.bb.bottom - p[0].grip.bb.bottom == 130 mm, "handle 130 mm below the head"
    assert p[0].grip.bb.width == 25 mm, "handle 25 mm wide"
    assert p[0].hang.c.center.y - p[0].grip.bb.bottom == 12.5 mm, "hanging hole 12.5 mm from the end"
    for i in range(4) {
        assert p[i].mark.l.bb.height <= 90 mm and p[i].mark.l.bb.width <= 90 mm,
            "the letter keeps a rim inside the head"
    }
}
