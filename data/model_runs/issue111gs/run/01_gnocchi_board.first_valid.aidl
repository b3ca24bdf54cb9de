# Request: a gnocchi board for my sister's kitchen, cut from 6 mm beech ply.
# 200 mm long overall: a 140 x 70 mm paddle with R8 corners and a handle 28 mm
# wide that sticks out 60 mm past the paddle and ends in a full round end, with an
# 8 mm hanging hole centred 12 mm from the handle's end. The paddle's face gets 20
# engraved (filled) ridges, each 3 mm wide and 58 mm long, running across the
# board at a 6 mm pitch, the group centred on the paddle. "GNOCCHI" engraved in
# filled bold letters (at most 7 mm tall) on the handle, centred between the
# paddle and the hanging hole. The inside corners where the handle meets the
# paddle are rounded R6.

units mm
thickness 6 mm

solid board {
    paddle = RoundedRectangle(center=(70, 0), width=140, height=70, corner_radius=8)
    # the handle's round far end is the board's end; its other end hides in the paddle
    handle = Slot(center=(156, 0), length=88, width=28)
    Fillet([paddle, handle], 6)

    hole hang {
        eye = Circle(center=(188, 0), diameter=8)
    }

    drawing ridges {
        r = Rectangle(center=(13, 0), width=3, height=58, fill=true)
        rs = LinearPattern(r, 20, (6, 0))
    }
    CenterInside(ridges, paddle)

    drawing name {
        t = Text("GNOCCHI", position=(162, 0), size=7, font="sans:Bold", valign="middle",
                 fill=true, max_width=36)
    }
    AlignCenterY(name, handle)
    name.bb.center_x == (paddle.bb.right + hang.bb.left) / 2

    # the request's numbers
    assert handle.bb.right - paddle.bb.left == 200 mm, "200 mm overall"
    assert paddle.width == 140 mm and paddle.height == 70 mm, "paddle 140 x 70"
    assert handle.bb.right - paddle.bb.right == 60 mm, "handle sticks out 60 mm"
    assert handle.width == 28 mm, "handle 28 mm wide"
    assert hang.eye.diameter == 8 mm, "8 mm hanging hole"
    assert handle.bb.right - hang.eye.center.x == 12 mm, "hole 12 mm from the end"
    assert len(ridges.rs) == 20, "20 ridges"
    assert ridges.rs[1].center.x - ridges.rs[0].center.x == 6 mm, "6 mm pitch"
    assert ridges.rs[0].width == 3 mm and ridges.rs[0].height == 58 mm, "ridge 3 x 58"
    assert abs(ridges.bb.center_x - paddle.bb.center_x) < 0.01 mm, "ridges centred"
    assert ridges.bb.left - paddle.bb.left >= 8 mm, "ridges clear of the paddle's ends"
    assert name.t.size <= 7 mm, "letters at most 7 mm"
    assert name.bb.left - paddle.bb.right >= 2 mm, "name clear of the paddle"
    assert hang.bb.left - name.bb.right >= 2 mm, "name clear of the hole"
    assert handle.bb.top - name.bb.top >= 3 mm, "name inside the handle"
}
