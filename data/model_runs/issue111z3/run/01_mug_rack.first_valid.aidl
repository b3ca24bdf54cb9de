# Kitchen mug rack: a wall board 300 x 70 mm with 6 mm corner radii, cut from 6 mm birch ply.
# Five 3 mm pilot holes for screw-in cup hooks, 55 mm apart, centred along the board, 20 mm above
# its bottom edge. Two 4.5 mm screw holes countersunk 9 mm (M4 flat heads), 20 mm in from each
# end, at mid height (35 mm). "COFFEE" engraved in filled sans Bold letters 14 mm high, centred
# horizontally, its capitals' middle 50 mm above the bottom edge.

units mm
thickness 6 mm

param width = 300 mm, min = 200, max = 400
param height = 70 mm, min = 50, max = 100
param hooks = 5, min = 2, max = 6
param pitch = 55 mm, min = 35, max = 70

solid rack {
    board = RoundedRectangle(center=(0, 0), width=width, height=height, corner_radius=6)

    hole pilot {
        c = Circle(center=(0, 0), diameter=3)
    }
    pilots = LinearPattern(pilot, hooks, (pitch, 0))
    # the row of pilots is centred on the board, 20 mm above its bottom edge
    pilots[0].c.center.x == board.center.x - (hooks - 1) * pitch / 2
    pilots[0].c.center.y == board.bb.bottom + 20

    hole screw {
        c = Circle(center=(-130, 0), diameter=4.5)
    }
    screws = Mirrored(screw, about=Line((0, -40), (0, 40), construction=true))
    screw.c.center.x == board.bb.left + 20
    screw.c.center.y == board.bb.bottom + 35
    Countersink([screw, screws], diameter=9)

    drawing label {
        word = Text("COFFEE", position=(0, 15), size=14, font="sans:Bold", valign="middle", fill=true)
    }
    label.word.position.x == board.center.x
    label.word.position.y == board.bb.bottom + 50

    assert board.bb.width == 300 mm, "board 300 wide"
    assert board.bb.height == 70 mm, "board 70 high"
    assert len(pilots) == 5, "five hooks"
    assert pilots[1].c.center.x - pilots[0].c.center.x == 55 mm, "hooks 55 apart"
    assert pilots[0].c.center.y - board.bb.bottom == 20 mm, "hooks 20 above the bottom"
    assert screw.c.center.x - board.bb.left == 20 mm, "screw 20 in from the left end"
    assert board.bb.right - screws.c.center.x == 20 mm, "screw 20 in from the right end"
    assert screw.c.center.y - board.bb.bottom == 35 mm, "screws at mid height"
    assert label.word.size == 14 mm, "letters 14 high"
}
