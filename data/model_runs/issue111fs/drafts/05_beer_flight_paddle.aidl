# Request (parties): "A beer tasting paddle for our home-brew party, in two layers of 6 mm oak ply
# glued together: a board 380 x 110 mm with R10 corners and a handle 120 mm long and 40 mm wide
# beyond its right end, with a round end and a 12 mm hanging hole centred in it; R15 fillets where
# the handle meets the board. The top layer has four 60 mm holes at 90 mm pitch, centred along the
# board and 10 mm behind its middle line, so the solid bottom layer makes them 6 mm deep wells for
# the tasting glasses. On the top layer, the numbers 1 to 4 fill-engraved in front of each well
# (10 mm tall) and "FLIGHT" engraved along the handle, each at least 5 mm from any hole."

thickness 6 mm
t = 6 mm
L = 380 mm
B = 110 mm
grip_l = 120 mm
grip_w = 40 mm
wells = 4
pitch = 90 mm

def layer(top=true) -> solid {
    board = RoundedRectangle(bottom_left=(0, -B / 2), width=L, height=B, corner_radius=10)
    grip = Rectangle(bottom_left=(L - 10 mm, -grip_w / 2), width=grip_l - grip_w / 2 + 10 mm,
                     height=grip_w)
    end = Circle(center=(L + grip_l - grip_w / 2, 0), diameter=grip_w)
    # FIX after the first valid program: W0406, Fillet([board, grip], 15) gave only 12.5 mm (a
    # corner takes at most half of the board's 25 mm edge piece); the two R15 fillets are drawn
    # instead as webs: a 15 mm square in each corner minus the fillet's circle (cuts only the web)
    solid web_top {
        sq = Rectangle(bottom_left=(L, grip_w / 2), width=15, height=15)
        hole arc { c = Circle(center=(L + 15 mm, grip_w / 2 + 15 mm), radius=15) }
    }
    solid web_bottom {
        sq = Rectangle(bottom_left=(L, -grip_w / 2 - 15 mm), width=15, height=15)
        hole arc { c = Circle(center=(L + 15 mm, -grip_w / 2 - 15 mm), radius=15) }
    }
    hole hang {
        c = Circle(center=(L + grip_l - grip_w / 2, 0), diameter=12)
    }
    if top {
        hole well {
            for i in range(wells) {
                w = Circle(center=(L / 2 + (i - (wells - 1) / 2) * pitch, 10), diameter=60)
            }
        }
        drawing numbers {
            for i in range(wells) {
                n = Text(str(i + 1), position=(L / 2 + (i - (wells - 1) / 2) * pitch, -38), size=10,
                         font="sans:Bold", valign="middle", fill=true)
            }
        }
        drawing name {
            f = Text("FLIGHT", position=(L + 45 mm, 0), size=9, valign="middle")
        }
    }
}

assembly paddle {
    upper = layer(top=true)
    lower = layer(top=false)
    Below(lower, upper, gap=10)
    AlignLeft(lower, upper)

    # 3D: the bottom layer on the table, the top layer glued on it
    Place(lower, position=(0, 0, 0))
    Place(upper, position=(0, 0, t))

    # the request's numbers
    assert upper.board.width == 380 mm and upper.board.height == 110 mm, "board 380 x 110"
    assert upper.end.bb.right - upper.board.bb.right == 120 mm, "handle 120 mm long"
    assert upper.grip.height == 40 mm and upper.end.diameter == 40 mm, "handle 40 wide, round end"
    assert upper.hang.c.diameter == 12 mm, "12 mm hanging hole"
    assert distance(upper.hang.c.center, upper.end.center) == 0 mm, "hole centred in the round end"
    assert len(upper.well.w) == 4, "four wells"
    assert upper.well.w[0].diameter == 60 mm, "60 mm wells"
    assert upper.well.w[1].center.x - upper.well.w[0].center.x == 90 mm, "90 mm pitch"
    assert abs((upper.well.w[0].center.x + upper.well.w[3].center.x) / 2 - upper.board.center.x) < 0.001 mm, "wells centred along the board"
    assert upper.well.w[0].center.y - upper.board.center.y == 10 mm, "10 mm behind the middle line"
    assert upper.well.bb.top <= upper.board.bb.top - 5 mm, "rim behind the wells"
    assert upper.well.bb.right <= upper.board.bb.right - 5 mm, "web before the handle"
    assert len(upper.numbers.n) == 4, "numbers 1 to 4"
    for i in range(4) {
        assert distance(upper.numbers.n[i], upper.well) >= 5 mm, "number clear of the wells"
        assert upper.numbers.n[i].bb.bottom >= upper.board.bb.bottom + 5 mm, "number on the board"
    }
    assert distance(upper.name, upper.hang) >= 5 mm, "FLIGHT clear of the hanging hole"
    assert upper.name.bb.left >= upper.board.bb.right + 5 mm, "FLIGHT on the handle"
    assert upper.name.bb.height <= upper.grip.height - 10 mm, "FLIGHT inside the handle's width"
}
