# Kitchen paper-towel holder, 4 mm plywood. A base 280 x 140 mm with R10 corners; two uprights
# 140 mm wide and 150 mm tall (straight sides, a round top of R70), each with a 38 mm dowel hole
# 80 mm above its bottom edge (the round top's centre) and two tabs 20 mm wide, 4 mm long on its
# bottom edge, centred 35 mm either side of its middle. The base has four 4.2 x 20.2 mm slots
# for the tabs, the two uprights 250 mm apart centre to centre (slot centres at x = +-125,
# y = +-35). "PAPER TOWELS" engraved 8 mm high in the middle of the base.
units mm
thickness 4 mm

param t = 4 mm, min = 3 mm, max = 6 mm

def upright() -> solid {
    body = Rectangle(center=(0, 40), width=140, height=80)
    top = Circle(center=(0, 80), radius=70)
    for k in range(2) {
        tab = Rectangle(center=(-35 + 70 * k, -t / 2), width=20, height=t)
    }
    hole dowel {
        c = Circle(center=(0, 80), diameter=38)
    }
}

assembly holder {
    solid base {
        board = RoundedRectangle(center=(0, 0), width=280, height=140, corner_radius=10)
        hole slots {
            for i in range(2) {
                for j in range(2) {
                    s = Rectangle(center=(-125 + 250 * i, -35 + 70 * j), width=t + 0.2, height=20.2)
                }
            }
        }
        drawing label {
            word = Text("PAPER TOWELS", (0, 0), size=8, valign="middle")
        }
    }
    left = upright()
    right = upright()
    RightOf(left, base, gap=10)
    AlignBottom(left, base)
    RightOf(right, left, gap=10)
    AlignBottom(right, left)

    assert base.board.bb.width == 280 mm, "base 280 long"
    assert base.board.bb.height == 140 mm, "base 140 deep"
    assert left.body.bb.width == 140 mm, "upright 140 wide"
    assert left.top.bb.top - left.body.bb.bottom == 150 mm, "upright 150 tall"
    assert left.bb.height == 154 mm, "150 plus 4 mm tabs"
    assert left.dowel.c.diameter == 38 mm, "38 mm dowel hole"
    assert left.dowel.c.center.y - left.body.bb.bottom == 80 mm, "dowel 80 above the bottom edge"
    assert left.tab[0].bb.width == 20 mm and left.tab[0].bb.height == 4 mm, "tabs 20 x 4"
    assert left.tab[1].center.x - left.tab[0].center.x == 70 mm, "tabs 35 either side"
    assert (left.tab[0].center.x + left.tab[1].center.x) / 2 == left.body.center.x, "tabs centred"
    assert base.slots.s[1][0].center.x - base.slots.s[0][0].center.x == 250 mm, "uprights 250 apart"
    assert base.slots.s[0][1].center.y - base.slots.s[0][0].center.y == 70 mm, "slots 35 either side"
    assert base.slots.s[0][0].bb.width == 4.2 mm and base.slots.s[0][0].bb.height == 20.2 mm, "slots 4.2 x 20.2"
    assert base.slots.s[0][0].center.x - base.board.center.x == -125 mm, "slots at x = -125"
    assert base.label.word.size == 8 mm, "text 8 mm"
}
