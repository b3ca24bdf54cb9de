# Door sign, 3 mm birch plywood: a 200 x 70 mm board with 8 mm rounded corners
# and two 4 mm screw holes centered vertically, 8 mm in from the left and right
# ends. The word "WORKSHOP" engraved at most 25 mm tall but never wider than the
# 160 mm between the screw holes' clear zone, and "EST. 2026" below it, 6 mm
# tall; the two lines centered on the board as a block with a 7 mm gap.

units mm
thickness 3 mm

param title_w = 160 mm, min = 80 mm, max = 170 mm

solid sign {
    board = RoundedRectangle(center=(0, 0), width=200, height=70, corner_radius=8)

    hole screw {
        c = Circle(center=(-92, 0), diameter=4)
    }
    At(screw.c.center, board.left.midpoint, dx=8)
    axis = Line(board.top.midpoint, board.bottom.midpoint, construction=true)
    screw2 = Mirrored(screw, about=axis)

    drawing title {
        t = Text("WORKSHOP", position=(0, 5), size=25, max_width=title_w)
    }
    drawing year {
        t = Text("EST. 2026", position=(0, -20), size=6)
    }
    Below(year, title, gap=7)
    AlignCenterX(title, board)
    AlignCenterX(year, board)
    (title.bb.top + year.bb.bottom) / 2 == board.center.y
}
