# Request: a peg board for our deep kitchen drawer, so plates and bowls stand between
# pegs. 12 mm birch ply, 540 x 380 mm (the drawer is 550 x 390 inside), corners R10. A grid
# of 20 mm holes for 20 mm beech dowel pegs, 11 columns by 7 rows at 45 mm pitch, centred on
# the board. Two lifting slots 80 x 22 mm (round ends) along the front edge, their centres
# 22 mm from it and 135 mm either side of the middle, and "FRONT" engraved 8 mm tall midway
# between them. Laser kerf 0.15 mm so the pegs fit snug.

units mm
thickness 12 mm
kerf 0.15 mm

param board_w = 540 mm, min = 300 mm, max = 580 mm
param board_h = 380 mm, min = 250 mm, max = 390 mm
param cols = 11, min = 5, max = 11
param rows = 7, min = 3, max = 7
PITCH = 45 mm
PEG_D = 20 mm

solid pegboard {
    board = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=10)

    hole peg {
        c = Circle(center=(-(cols - 1) * PITCH / 2, -(rows - 1) * PITCH / 2), diameter=PEG_D)
    }
    grid = GridPattern(peg, rows, cols, PITCH)

    hole lift {
        left = Slot(center=(-135, -board_h / 2 + 22), length=80, width=22)
        right = Slot(center=(135, -board_h / 2 + 22), length=80, width=22)
    }

    drawing label {
        t = Text("FRONT", position=(0, -board_h / 2 + 22), size=8, valign="middle")
    }

    assert len(grid) == 11 * 7, "11 columns by 7 rows"
    assert board.bb.width == 540 mm and board.bb.height == 380 mm, "540 x 380"
    assert grid[1].c.center.x - grid[0].c.center.x == 45 mm, "45 mm pitch across"
    assert grid[cols].c.center.y - grid[0].c.center.y == 45 mm, "45 mm pitch up"
    assert grid[0].c.diameter == 20 mm, "20 mm peg holes"
    assert (grid[0].c.center.x - board.bb.left) == (board.bb.right - grid[len(grid) - 1].c.center.x),
        "centred across"
    assert (grid[0].c.center.y - board.bb.bottom) == (board.bb.top - grid[len(grid) - 1].c.center.y),
        "centred front to back"
    assert lift.left.center.y - board.bb.bottom == 22 mm, "slots 22 from the front edge"
    assert lift.right.center.x - lift.left.center.x == 270 mm, "135 either side of the middle"
    assert lift.left.bb.width == 80 mm and lift.left.bb.height == 22 mm, "slots 80 x 22"
    assert distance(lift, peg) >= 5 mm, "a web of wood between a slot and the nearest peg hole"
}
