# Garden seed-spacing template: a 300 x 230 mm board of 3 mm acrylic with 8 mm rounded
# corners, laid on the seed bed; poke a hole through each opening to sow. 35 holes of
# 8 mm in 5 rows x 7 columns, 40 mm apart both ways (grid centres span 240 x 160 mm),
# the grid centred left to right, its bottom row 25 mm above the bottom edge. A handle
# slot 80 x 20 mm (round ends) centred left to right, its centre 20 mm below the top edge.
# "SPACING 40 MM" engraved 6 mm high, centred, baseline 8 mm above the bottom edge.

units mm
thickness 3 mm

param pitch = 40 mm, min = 25 mm, max = 45 mm
param seed_d = 8 mm, min = 5 mm, max = 12 mm

solid template {
    board = RoundedRectangle(center=(0, 0), width=300, height=230, corner_radius=8)

    hole seed { c = Circle(center=(-120, -90), diameter=seed_d) }
    seeds = GridPattern(seed, 5, 7, (pitch, pitch))
    seed.c.center.x == board.bb.left + (300 mm - 6 * pitch) / 2
    seed.c.center.y == board.bb.bottom + 25

    hole handle { grip = Slot(center=(0, 95), length=80, width=20) }
    AlignCenterX(handle, board)
    handle.grip.center.y == board.bb.top - 20

    drawing label {
        word = Text("SPACING 40 MM", position=(0, -107), size=6)
    }
    AlignCenterX(label, board)
    label.word.position.y == board.bb.bottom + 8

    assert board.bb.width == 300 mm, "board 300 mm wide"
    assert board.bb.height == 230 mm, "board 230 mm high"
    assert len(seeds) == 35, "35 holes"
    assert seed.c.diameter == 8 mm, "8 mm holes"
    assert seeds[34].c.center.x - seeds[0].c.center.x == 240 mm, "columns span 240 mm"
    assert seeds[34].c.center.y - seeds[0].c.center.y == 160 mm, "rows span 160 mm"
    assert seeds[1].c.center.x - seeds[0].c.center.x == 40 mm, "40 mm across"
    assert (seeds[0].c.center.x + seeds[34].c.center.x) / 2 == board.bb.center_x, "grid centred"
    assert seeds[0].c.center.y - board.bb.bottom == 25 mm, "bottom row 25 mm up"
    assert handle.grip.length == 80 mm, "handle 80 mm long"
    assert handle.grip.width == 20 mm, "handle 20 mm wide"
    assert board.bb.top - handle.grip.center.y == 20 mm, "handle 20 mm below the top"
    assert handle.bb.bottom > seeds[34].c.bb.top, "handle clear of the top row"
    assert label.word.position.y - board.bb.bottom == 8 mm, "text baseline 8 mm up"
    assert label.bb.top < seeds[0].c.bb.bottom, "text under the bottom row"
}
