# Sport: golf-ball display rack, 3 mm plywood, three parts. Top: 200 x 150 mm, 10 mm rounded
# corners, 12 holes of 36 mm (a ball sits in each) in 3 rows of 4, 45 mm apart both ways,
# the grid centred on the top. Near each short end two slots 20.2 x 3.2 mm along the short
# side, centred 91.5 mm from the top's centre in x and 40 mm either side of it in y, for the
# legs' tabs. Two legs: 150 x 50 mm, each with two 20 x 3 mm tabs on its top edge centred
# 40 mm either side of its middle; "GOLF CLUB" engraved on each leg, 8 mm text, centred.
# Layout for cutting: the legs side by side 5 mm apart, 5 mm below the top.

thickness 3 mm

def leg() -> solid {
    board = Rectangle(center=(0, 0), width=150, height=50)
    tab_l = Rectangle(center=(-40, 26.5), width=20, height=3)
    tab_r = Rectangle(center=(40, 26.5), width=20, height=3)
    drawing label {
        t = Text("GOLF CLUB", (0, 0), size=8, valign="middle")
    }
    assert board.width == 150 mm and board.height == 50 mm, "leg 150 x 50"
    assert tab_r.center.x - board.center.x == 40 mm, "tabs 40 mm from the middle"
    assert tab_l.bb.bottom == board.bb.top, "tabs on the top edge"
}

assembly rack {
    solid top {
        board = RoundedRectangle(center=(0, 0), width=200, height=150, corner_radius=10)
        hole ball {
            c = Circle(center=(-67.5, -45), diameter=36)
        }
        grid = GridPattern(ball, 3, 4, 45)
        hole slots {
            for sx in [-1, 1] {
                for sy in [-1, 1] {
                    s = Rectangle(center=(sx * 91.5, sy * 40), width=3.2, height=20.2)
                }
            }
        }
    }

    leg_a = leg()
    leg_b = leg()
    Below(leg_a, top, gap=5)
    AlignLeft(leg_a, top)
    RightOf(leg_b, leg_a, gap=5)
    AlignCenterY(leg_b, leg_a)

    assert top.board.width == 200 mm and top.board.height == 150 mm, "top 200 x 150"
    assert len(top.grid) == 12, "12 ball holes"
    assert top.ball.c.diameter == 36 mm, "36 mm holes"
    assert top.board.center.x - top.ball.c.center.x == 1.5 * 45 mm, "4 columns 45 apart, centred"
    assert top.board.center.y - top.ball.c.center.y == 45 mm, "3 rows 45 apart, centred"
    assert len(top.slots.s) * len(top.slots.s[0]) == 4, "four slots"
    assert top.slots.s[0][0].width == 3.2 mm and top.slots.s[0][0].height == 20.2 mm, "slots 20.2 x 3.2"
    assert abs(top.slots.s[0][0].center.x - top.board.center.x) == 91.5 mm, "slots 91.5 mm out"
    assert abs(top.slots.s[0][0].center.y - top.board.center.y) == 40 mm, "slots 40 mm either side"
    assert leg_a.label.t.size == 8 mm, "8 mm text"
    assert top.bb.bottom - leg_a.bb.top == 5 mm, "legs 5 mm below the top"
    assert leg_b.bb.left - leg_a.bb.right == 5 mm, "legs 5 mm apart"
}
