# Flat chess rook for a laser-cut chess set: 40 mm wide base, 70 mm tall silhouette,
# symmetric: a 40 x 8 mm base, a 32 x 4 mm collar on it, a body tapering from 24 mm to
# 20 mm over 38 mm, a 30 mm wide, 16 mm tall head whose top has three 6 mm wide, 6 mm deep
# crenel notches (one centered, two 12 mm either side), and a 3 mm wide, 10 mm deep
# slot up from the middle of the base so two rooks cross-halve into a 3D piece? no: a flat
# piece standing in a slotted board: a 20 x 3 mm tab under the base.

solid rook {
    outline = Polygon([(0, 0), (20, 0), (20, 8), (16, 8), (16, 12), (12, 12), (10, 50),
                       (15, 50), (15, 66), (0, 66)], mirror="y")
    hole crenels {
        for i in range(3) {
            n = Rectangle(center=(-12 + 12 * i, 63), width=6, height=6)
        }
    }
    crenels.n[1].center.x == outline.bb.center_x
    crenels.bb.top == outline.bb.top
    solid tab {
        t = Rectangle(center=(0, -2), width=20, height=4)
    }
    AlignCenterX(tab, outline)
    Below(tab, outline)
    assert outline.bb.width == 40 mm, "40 mm base"
    assert outline.bb.height + tab.bb.height == 70 mm, "70 mm tall with the tab"
    assert len(crenels.n) == 3, "three crenels"
}
