# Key rack: a wall board 200 mm x 50 mm with 6 mm rounded corners and two 4.5 mm
# screw holes 12 mm from each end, centred vertically; below it five J-hooks, each a
# stem 8 mm wide hanging 30 mm below the board and a 8 mm x 14 mm upturned tip to the
# right of the stem's foot (a 12 mm wide mouth); hooks 36 mm apart, centred on the board.
param hooks = 5, min = 2, max = 5

solid rack {
    board = RoundedRectangle(center=(0, 0), width=200, height=50, corner_radius=6)
    hole screws {
        l = Circle(center=(-88, 0), diameter=4.5)
        r = Circle(center=(88, 0), diameter=4.5)
    }
    At(screws.l.center, board.left.midpoint, dx=12)
    At(screws.r.center, board.right.midpoint, dx=-12)

    solid hook {
        stem = Rectangle(center=(-72, -40), width=8, height=30)
        foot = Rectangle(center=(-62, -51), width=28, height=8)
        tip = RoundedRectangle(center=(-52, -45), width=8, height=14, corner_radii=[4, 4, 0, 0])
        AlignLeft(foot, stem)
        AlignBottom(foot, stem)
        AlignRight(tip, foot)
        AlignBottom(tip, foot)
    }
    Below(hook.stem, board)
    row = LinearPattern(hook, hooks, (36, 0))
    hook.bb.center_x == board.center.x - (hooks - 1) * 36 / 2
}
