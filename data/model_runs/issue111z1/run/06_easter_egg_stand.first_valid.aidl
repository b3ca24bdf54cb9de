# Holidays: an Easter egg stand (cut a set of six), 3 mm birch ply: two identical-looking pieces
# slotted crosswise. Each piece 60 mm wide and 45 mm tall: flat bottom, straight sides, the top a
# concave arc (the cup the egg sits in) from corner to corner, dipping 12 mm at the middle
# (33 mm of material there). Cross-halving slots at the middle, 3 mm + 0.1 mm clearance wide:
# piece A slotted from the bottom 16.5 mm up, piece B from the cup's lowest point 16.5 mm down.
# A small engraved egg (an 8 x 11 mm ellipse) on each piece's side, 12 mm from its left edge,
# 14 mm up.
thickness 3 mm

import "std/joints.aidl"

param w = 60 mm, min = 40, max = 90
param h = 45 mm, min = 30, max = 70
param dip = 12 mm, min = 5, max = 20
param ply = 3 mm, min = 2, max = 6

def egg_piece(from_top=false) -> solid {
    base = Line((-w / 2, 0), (w / 2, 0))
    right = Line((w / 2, 0), (w / 2, h))
    cup = Arc(start=(w / 2, h), through=(0, h - dip), end=(-w / 2, h))
    left = Line((-w / 2, h), (-w / 2, 0))
    if from_top {
        slot = cross_halving(depth=(h - dip) / 2, thickness=ply, clearance=0.1 mm, cx=0 mm,
                             cy=h - dip)
    } else {
        slot = cross_halving(depth=(h - dip) / 2, thickness=ply, clearance=0.1 mm,
                             rotation=180 deg, cx=0 mm, cy=0 mm)
    }
    drawing deco {
        egg = Ellipse(center=(-w / 2 + 12, 14), rx=4, ry=5.5)
    }
}

assembly egg_stand {
    a = egg_piece(from_top=false)
    b = egg_piece(from_top=true)
    RightOf(b, a, gap=8)
    AlignBottom(b, a)

    assert a.bb.width == 60 mm and a.bb.height == 45 mm, "60 x 45 pieces"
    assert a.slot.depth + b.slot.depth == 33 mm, "the slots meet: 33 mm of material at the middle"
    assert a.slot.depth == 16.5 mm, "16.5 mm slots"
}
