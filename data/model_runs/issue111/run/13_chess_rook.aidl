# Flat chess rook for a laser-cut chess set: 40 mm wide base, 70 mm tall with its tab,
# symmetric: a 40 x 8 mm base, a 32 x 4 mm collar on it, a body tapering from 24 mm to
# 20 mm over 38 mm, a 30 mm wide, 16 mm tall head whose top has three 6 mm merlons (two at
# the corners, one centered) between two 6 mm wide, 6 mm deep notches; a 20 x 4 mm tab
# under the base to stand in a slotted board.
# (fixed after the render: the first program's three notches at -12, 0, 12 mm opened the
# head's corners, leaving two merlons)

solid rook {
    outline = Polygon([(0, 0), (20, 0), (20, 8), (16, 8), (16, 12), (12, 12), (10, 50),
                       (15, 50), (15, 66), (0, 66)], mirror="y")
    hole crenels {
        for i in range(2) {
            n = Rectangle(center=(-6 + 12 * i, 63), width=6, height=6)
        }
    }
    AlignCenterX(crenels, outline)
    crenels.bb.top == outline.bb.top
    solid tab {
        t = Rectangle(center=(0, -2), width=20, height=4)
    }
    AlignCenterX(tab, outline)
    Below(tab, outline)
    assert outline.bb.width == 40 mm, "40 mm base"
    assert outline.bb.height + tab.bb.height == 70 mm, "70 mm tall with the tab"
    assert len(crenels.n) == 2, "two notches, three merlons"
    assert crenels.bb.left - outline.bb.center_x == -9 mm, "corner merlons 6 mm wide"
}
