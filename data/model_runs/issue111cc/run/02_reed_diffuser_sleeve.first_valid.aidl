# Request: a slip-over sleeve for the square reed-diffuser bottle in our bathroom (56 x 56 mm,
# 90 mm to the shoulder, a 20 mm neck). 3 mm poplar ply, a finger-jointed box 64 x 64 x 96 mm
# outside with 10 mm fingers, open at the bottom so it drops over the bottle; the closed end is
# the top and has a 24 mm hole in its middle for the neck and reeds. Every side has a grid of
# rounded windows (8 x 12 mm, corners r2, 14 mm apart across and 16 mm apart up and down,
# 3 across and 4 high) so the oil shows; the grid starts 20 mm below the top edge. On the
# front "LAVENDER" is engraved in 6 mm letters centred 11 mm below the top edge, upright when
# the sleeve stands over the bottle.

import "std/joints.aidl"

thickness 3 mm

def windows(cols=3, rows=4, w=8 mm, h=12 mm, px=14 mm, py=16 mm) -> hole {
    win = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=2 mm)
    grid = GridPattern(win, rows, cols, (px, py))
}

assembly sleeve {
    # finger_box's "bottom" is the sleeve's top: the open side goes down over the bottle
    box = finger_box(length=64 mm, depth=64 mm, height=96 mm, thickness=3 mm, finger=10 mm,
                     closed=false)

    hole neck { c = Circle(center=(0, 0), diameter=24 mm) }
    CenterInside(neck, box.bottom)
    CutInto(neck, box.bottom)

    # front and back lie upright, their bottom edge (the sleeve's top) at -y
    front_win = windows()
    AlignCenterX(front_win, box.front)
    front_win.bb.bottom == box.front.bb.bottom + 20 mm
    CutInto(front_win, box.front)

    back_win = windows()
    AlignCenterX(back_win, box.back)
    back_win.bb.bottom == box.back.bb.bottom + 20 mm
    CutInto(back_win, box.back)

    # the sides lie on their side, their bottom edge (the sleeve's top) toward the middle:
    # the grid turned a quarter, 4 across and 3 high
    left_win = windows(cols=4, rows=3, w=12 mm, h=8 mm, px=16 mm, py=14 mm)
    AlignCenterY(left_win, box.left)
    left_win.bb.right == box.left.bb.right - 20 mm
    CutInto(left_win, box.left)

    right_win = windows(cols=4, rows=3, w=12 mm, h=8 mm, px=16 mm, py=14 mm)
    AlignCenterY(right_win, box.right)
    right_win.bb.left == box.right.bb.left + 20 mm
    CutInto(right_win, box.right)

    # upside down on the flat front: it reads upright when the sleeve is turned over
    drawing label {
        word = Text("LAVENDER", position=(0, 0), size=6 mm, rotation=180 deg, valign="middle")
    }
    AlignCenterX(label, box.front)
    label.bb.center_y == box.front.bb.bottom + 11 mm
    CutInto(label, box.front)

    # shown as used: turned over, standing on its open edge
    Place(box, rotation=(180 deg, 0, 0), position=(0, 0, 96 mm))

    assert box.front.bb.width == 64 mm and box.left.bb.height == 64 mm, "64 x 64 outside"
    assert box.front.bb.height == 96 mm, "96 mm tall"
    assert neck.c.diameter == 24 mm, "24 mm neck hole"
    assert len(front_win.grid) == 12 and len(left_win.grid) == 12, "3 x 4 windows a side"
    assert box.front.bb.top - front_win.bb.top >= 6 mm, "grid clear of the open edge"
    assert label.bb.center_y - box.front.bb.bottom == 11 mm, "label 11 mm below the top edge"
}
