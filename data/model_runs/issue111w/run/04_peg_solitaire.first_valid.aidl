# Toys: an English peg-solitaire board, 6 mm plywood (glued onto a plain
# 180 mm disc), a 180 mm disc with 33 peg holes 6.2 mm in the cross-shaped
# English layout (a 7 x 7 grid on a 20 mm pitch without its 2 x 2 corner
# blocks), centred on the disc. An engraved border circle 170 mm, and an
# engraved 11 mm ring round the centre hole (the one left empty at the start).

thickness 6 mm
param pitch = 20 mm, min = 16, max = 24
param peg_d = 6.2 mm, min = 4, max = 8

solid board {
    disc = Circle(center=(0, 0), diameter=180)
    hole pegs {
        for k in range(49) {
            if abs(k // 7 - 3) <= 1 or abs(k % 7 - 3) <= 1 {
                c = Circle(center=((k % 7 - 3) * pitch, (k // 7 - 3) * pitch), diameter=peg_d)
            }
        }
    }
    drawing marks {
        border = Circle(center=(0, 0), diameter=170)
        start = Circle(center=(0, 0), diameter=11)
    }
    assert disc.diameter == 180 mm, "180 mm disc"
    assert len(pegs.c) == 33, "33 holes"
    assert pegs.bb.width == 6 * 20 mm + 6.2 mm, "7 holes on 20 mm across"
    assert marks.border.diameter == 170 mm, "border 170"
}
