# A Raspberry-Pi-style mounting plate: the 85 x 56 mm board outline (engraved),
# four M2.5 mounting holes 3.5 mm from the board's edges at 58 x 49 mm spacing,
# a 3 mm margin plate around the board and a rectangular connector cutout
# flush with the plate's right edge.

param board_w = 85 mm
param board_h = 56 mm
param margin = 3 mm
param m25 = 2.7 mm       # clearance hole for M2.5
param conn_w = 10 mm     # how deep the connector cutout goes in from the edge
param conn_h = 20 mm

solid pi_plate {
    base = RoundedRectangle(center=(0, 0), width=board_w + 2 * margin,
                            height=board_h + 2 * margin, corner_radius=3)
    Fixed(base)

    drawing board {
        outline = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=3)
    }
    CenterInside(board, base)

    hole mount {
        m = Circle(center=(-board_w / 2 + 3.5, -board_h / 2 + 3.5), diameter=m25)
    }
    holes = GridPattern(mount, rows=2, cols=2, spacing=(58 mm, 49 mm))
    At(mount.m.center, board.outline.bottom_left, dx=3.5, dy=3.5)

    hole connector {
        c = Rectangle(center=(board_w / 2, 0), width=conn_w, height=conn_h)
    }
    AlignRight(connector, base)
    AlignCenterY(connector, base)
}
