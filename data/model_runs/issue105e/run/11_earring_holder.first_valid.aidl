# Earring holder: a 100 x 75 mm plate with 6 mm rounded corners; a grid of
# 4 rows x 6 columns of 2 mm holes for ear wires, 14 mm apart across and 12 mm
# apart down, the grid centered left-to-right and its center 5 mm below the
# plate's center; a 5 mm hanging hole centered 7 mm below the top edge.

param cols = 6, min = 2, max = 6
param rows = 4, min = 2, max = 4
param dx = 14 mm, min = 8 mm, max = 15 mm
param dy = 12 mm, min = 8 mm, max = 14 mm

solid holder {
    body = RoundedRectangle(center=(0, 0), width=100, height=75, corner_radius=6)
    hole pin { c = Circle(center=(-35, -23), diameter=2) }
    grid = GridPattern(pin, rows, cols, (dx, dy))
    # the first (bottom-left) hole, so that the grid's center is 5 mm below the plate's
    At(pin.c.center, body.center, dx=-(cols - 1) / 2 * dx, dy=-(rows - 1) / 2 * dy - 5 mm)

    hole hang { c = Circle(center=(0, 30), diameter=5) }
    At(hang.c.center, body.top.midpoint, dy=-7)

    assert len(grid) == 24, "4 x 6 = 24 holes"
    assert hang.bb.bottom > grid[len(grid) - 1].bb.top + 5 mm, "hanging hole clear of the grid"
}
