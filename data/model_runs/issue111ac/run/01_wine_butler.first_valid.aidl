# Kitchen: a wine butler (a caddy that carries a bottle and two glasses) cut from 6 mm oak
# ply. The board is 320 mm long and 110 mm wide at its middle, a smooth egg-like outline
# narrowing to round ends 80 mm wide. In its middle a 32 mm hole takes the bottle's neck.
# At each end a slot 13 mm wide, open to the end and 50 mm deep from the tip, takes a wine
# glass's stem (its inner end round). "CHEERS" and "SALUT" are engraved as filled serif
# letters 12 mm tall, each centred between the bottle hole and a glass slot.

units mm
thickness 6 mm

param length = 320 mm, min = 260 mm, max = 400 mm
param width = 110 mm, min = 90 mm, max = 140 mm
param end_w = 80 mm, min = 60 mm, max = 100 mm
param neck_d = 32 mm, min = 26 mm, max = 40 mm
param stem_w = 13 mm, min = 9 mm, max = 16 mm
param stem_depth = 50 mm, min = 35 mm, max = 70 mm
param letters = 12 mm, min = 8 mm, max = 16 mm

solid butler {
    board = Hull(Circle(center=(-(length / 2 - end_w / 2), 0), radius=end_w / 2),
                 Circle(center=(length / 2 - end_w / 2, 0), radius=end_w / 2),
                 Circle(center=(0, 0), radius=width / 2))

    hole neck {
        c = Circle(center=(0, 0), diameter=neck_d)
    }

    # the glass slots run in from each tip along the board's axis; their outer end runs
    # past the tip so the slot opens cleanly
    hole stems {
        for i in range(2) {
            s = Slot(start=((2 * i - 1) * (length / 2 + 10 mm), 0),
                     end=((2 * i - 1) * (length / 2 - stem_depth + stem_w / 2), 0), width=stem_w)
        }
    }

    drawing words {
        left = Text("CHEERS", position=(-70, 0), size=letters, font="serif", valign="middle",
                    fill=true)
        right = Text("SALUT", position=(70, 0), size=letters, font="serif", valign="middle",
                     fill=true)
    }
    # each word centred between the neck hole and its glass slot, on the board's axis
    words.left.position.x == (stems.s[0].bb.right + neck.bb.left) / 2
    words.right.position.x == (neck.bb.right + stems.s[1].bb.left) / 2
    words.left.position.y == board.center.y
    words.right.position.y == board.center.y

    # the request's own numbers
    assert board.bb.width == 320 mm, "board 320 mm long"
    assert board.bb.height == 110 mm, "board 110 mm wide at the middle"
    assert neck.c.diameter == 32 mm, "bottle neck hole 32 mm"
    assert stems.s[0].width == 13 mm and stems.s[1].width == 13 mm, "glass slots 13 mm wide"
    assert board.bb.right - stems.s[1].bb.left == 50 mm, "right glass slot 50 mm deep"
    assert stems.s[0].bb.right - board.bb.left == 50 mm, "left glass slot 50 mm deep"
    assert words.left.size == 12 mm and words.right.size == 12 mm, "letters 12 mm tall"
}
