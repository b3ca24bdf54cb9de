# Request (parties): a beer tasting-flight paddle for a home-brew party, from 6 mm oak ply.
# 400 mm long overall: a 280 x 100 mm board with 20 mm rounded corners and a 120 mm handle
# 36 mm wide with a fully rounded end, blended into the board with 15 mm fillets. Four holes
# 58 mm across for 5 oz tasting glasses, 68 mm apart, centred on the board, each with its
# number 1-4 engraved 6 mm tall centred 40 mm in front of the hole's centre. A 10 mm hanging
# hole 15 mm from the handle's end, and the brewery name "HOP HOUSE" engraved in filled
# serif letters 10 mm tall along the handle, clear of the hanging hole.

units mm
thickness 6 mm

param glasses = 4, min = 3, max = 5
param glass_d = 58 mm, min = 45 mm, max = 70 mm
param pitch = 68 mm, min = 55 mm, max = 80 mm

board_len = 280 mm
handle_len = 120 mm

solid paddle {
    board = RoundedRectangle(center=(0, 0), width=board_len, height=100, corner_radius=20)
    grip = RoundedRectangle(center=(board_len / 2 + handle_len / 2 - 2.5, 0),
                            width=handle_len + 5, height=36, corner_radii=[0, 18, 18, 0])
    Fillet(board, grip, 15)

    hole glass {
        c = Circle(center=(-(glasses - 1) * pitch / 2, 0), diameter=glass_d)
    }
    row = LinearPattern(glass, glasses, (pitch, 0))

    hole hang {
        c = Circle(center=(board_len / 2 + handle_len - 15, 0), diameter=10)
    }

    drawing numbers {
        for i in range(glasses) {
            n = Text(str(i + 1), position=(-(glasses - 1) * pitch / 2 + i * pitch, -40), size=6,
                     valign="middle")
        }
    }

    drawing name {
        w = Text("HOP HOUSE", position=(board_len / 2 + handle_len / 2 - 8, 0), size=10,
                 font="serif", valign="middle", fill=true)
    }

    Fixed(board)
    Fixed(grip)
    Fixed(glass)
    Fixed(hang)
    Fixed(numbers)
    Fixed(name)

    assert self.bb.width == 400 mm, "400 mm overall"
    assert board.bb.width == 280 mm and board.bb.height == 100 mm
    assert grip.bb.right - board.bb.right == 120 mm and grip.bb.height == 36 mm
    assert len(row) == 4
    assert row[1].c.center.x - row[0].c.center.x == 68 mm
    assert abs(row[0].c.center.x + row[3].c.center.x) < 0.001 mm, "glasses centred"
    assert row[0].c.diameter == 58 mm
    assert row[2].c.center.y - numbers.n[2].position.y == 40 mm, "number 40 mm in front"
    assert numbers.n[3].text == "4"
    assert grip.bb.right - hang.c.center.x == 15 mm
    assert name.bb.right < hang.c.left.x - 3 mm and name.bb.left > board.bb.right + 3 mm,
        "name on the handle, clear of the hanging hole"
}
