import "std/fasteners.aidl"
# Pi-style mounting plate: 85 x 56 board + 3 mm margin, four M2.5 holes, connector cutout on one edge
param bw = 85 mm
param bh = 56 mm
param margin = 3 mm
solid piplate {
    body = Rectangle(center=(0, 0), width=bw + 2 * margin, height=bh + 2 * margin)
    board = Rectangle(center=(0, 0), width=bw, height=bh, construction=true)
    Fixed(body)
    CenterInside(board, body)
    h = clearance_hole(size=2.5)
    holes = GridPattern(h, 2, 2, (58, 49))
    At(h.c.center, board.bottom_left, dx=3.5, dy=3.5)
    hole connector {
        r = Rectangle(center=(45, 0), width=12, height=20)
    }
    AlignRight(connector, body)
    AlignCenterY(connector, body)
}
