# Cheese board (6 mm hardwood ply): a 260 x 160 mm board with R15 corners and a
# handle at the right end: 90 mm long, 45 mm wide at the board tapering to
# 35 mm, its end rounded (a full half circle); a 20 mm hanging hole 18 mm from
# the handle's tip; "BRIE & CO" engraved 10 mm high along the board's bottom
# edge, centered, its baseline 12 mm above the edge; the handle's joint to the
# board rounded R10 on both sides.
thickness 6 mm

solid board {
    body = RoundedRectangle(center=(0, 0), width=260, height=160, corner_radius=15)
    # the neck runs from 10 mm inside the board to the end circle's center
    neck = Trapezoid(center=(130 + 36, 0), bottom_width=45, top_width=35, height=82.5,
                     rotation=-90 deg)
    tip = Circle(center=(130 + 72, 0), diameter=35)
    LeftOf(body, neck, gap=-10)
    AlignCenterY(neck, body)
    tip.center.x == body.bb.right + 90 mm - 17.5 mm
    AlignCenterY(tip, body)
    hole hang {
        c = Circle(center=(200, 0), diameter=20)
    }
    hang.c.center.x == tip.bb.right - 18 mm
    AlignCenterY(hang, body)
    drawing label {
        t = Text("BRIE & CO", position=(0, -68), size=10)
    }
    AlignCenterX(label, body)
    label.t.position.y == body.bb.bottom + 12 mm
    Fillet([body.right, neck.left], 10)
    Fillet([body.right, neck.right], 10)
}

assert board.body.bb.width == 260 mm and board.body.bb.height == 160 mm, "260 x 160"
assert board.tip.bb.right - board.body.bb.right == 90 mm, "handle 90 mm long"
assert board.tip.diameter == 35 mm, "35 mm at the end"
assert board.tip.bb.right - board.hang.c.center.x == 18 mm, "hole 18 mm from the tip"
assert board.label.t.position.y - board.body.bb.bottom == 12 mm, "baseline 12 mm up"
assert abs(board.neck.bb.right - board.tip.center.x) < 0.001 mm, "the neck ends at the round end's center: no step"
