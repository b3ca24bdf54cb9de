# Kitchen utensil hanging rail: a 300 x 60 mm board with 8 mm corner radii, 6 mm plywood;
# six 8 mm holes for S-hooks, 45 mm apart, centred, 15 mm below the top edge; two 4 mm
# screw holes countersunk for 8 mm heads, 15 mm in from each end, at mid height;
# "KITCHEN" engraved 8 mm tall, centred, 12 mm above the bottom edge.

thickness 6 mm

solid rail {
    board = RoundedRectangle(center=(0, 0), width=300, height=60, corner_radius=8)

    hole hook {
        c = Circle(center=(-112.5, 15), diameter=8)
    }
    hooks = LinearPattern(hook, 6, (45, 0))
    VerticalDistance(hook.c.center, board.top.midpoint, 15)
    HorizontalDistance(hook.c.center, board.center, 112.5)

    hole screw {
        s = Circle(center=(-135, 0), diameter=4)
    }
    other_screw = Mirrored(screw, about=Line((0, -40), (0, 40), construction=true))
    HorizontalDistance(board.left.midpoint, screw.s.center, 15)
    AlignCenterY(screw, board)
    Countersink(screw, diameter=8)
    Countersink(other_screw, diameter=8)

    drawing label {
        word = Text("KITCHEN", (0, -18), size=8)
    }
    AlignCenterX(label, board)
    label.word.position.y == board.bb.bottom + 12

    assert board.width == 300 mm, "300 long"
    assert board.height == 60 mm, "60 tall"
    assert len(hooks) == 6, "six hooks"
    assert hooks[1].c.center.x - hooks[0].c.center.x == 45 mm, "45 apart"
    assert board.bb.top - hooks[0].c.center.y == 15 mm, "15 below the top"
    assert hooks[0].c.diameter == 8 mm, "8 mm hooks"
    assert (hooks[0].c.center.x + hooks[5].c.center.x) / 2 == board.center.x, "centred"
    assert screw.s.center.x - board.bb.left == 15 mm, "15 in from the left"
    assert board.bb.right - other_screw.s.center.x == 15 mm, "15 in from the right"
    assert screw.s.center.y == board.center.y, "mid height"
    assert screw.s.diameter == 4 mm, "4 mm screws"
    assert label.word.size == 8 mm, "8 mm text"
    assert label.word.position.y - board.bb.bottom == 12 mm, "12 above the bottom"
}
