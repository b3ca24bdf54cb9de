# Request: a hanging holder for nesting material (wool, pet fur, dry grass) that garden
# birds pull out in spring, cut from 6 mm exterior ply. An open-top finger-jointed box,
# outside 100 x 100 mm and 160 mm tall, 16 mm fingers, filled from the open top. Every wall
# is a lattice of 16 mm square openings with R3 corners, 3 across on a 26 mm pitch and
# 5 up on a 24 mm pitch (15 per wall), centred across the wall, the lowest row's bottom
# 25 mm above the box's bottom edge. Four 6 mm drain holes in the bottom on a 40 mm square,
# centred. Two 6 mm cord holes, one in the left and one in the right wall, 12 mm below the
# top edge and centred, for a hanging cord. "NEST WOOL" engraved in 8 mm strokes on the
# front above the lattice, its baseline 145 mm above the bottom edge.

import "std/joints.aidl"

thickness 6 mm

def lattice(rows=5, cols=3, col_pitch=26 mm, row_pitch=24 mm) -> hole {
    o = RoundedRectangle(center=(0, 0), width=16 mm, height=16 mm, corner_radius=3 mm)
    g = GridPattern(o, rows, cols, col_spacing=col_pitch, row_spacing=row_pitch)
}

assembly nest_wool {
    box = finger_box(length=100 mm, depth=100 mm, height=160 mm, thickness=6 mm,
                     finger=16 mm, closed=false)

    # front and back stand upright in the net: rows go up (+y)
    front_l = lattice()
    AlignCenterX(front_l, box.front.outline)
    front_l.bb.bottom == box.front.outline.bb.bottom + 25 mm
    CutInto(front_l, box.front)

    back_l = lattice()
    AlignCenterX(back_l, box.back.outline)
    back_l.bb.bottom == box.back.outline.bb.bottom + 25 mm
    CutInto(back_l, box.back)

    # the sides lie on their side, top edge outward: "up" is -x on the left, +x on the right
    left_l = lattice(rows=3, cols=5, col_pitch=24 mm, row_pitch=26 mm)
    AlignCenterY(left_l, box.left.outline)
    left_l.bb.right == box.left.outline.bb.right - 25 mm
    CutInto(left_l, box.left)

    right_l = lattice(rows=3, cols=5, col_pitch=24 mm, row_pitch=26 mm)
    AlignCenterY(right_l, box.right.outline)
    right_l.bb.left == box.right.outline.bb.left + 25 mm
    CutInto(right_l, box.right)

    hole drains {
        d = Circle(center=(0, 0), diameter=6 mm)
        g = GridPattern(d, 2, 2, col_spacing=40 mm, row_spacing=40 mm)
    }
    CenterInside(drains, box.bottom.outline)
    CutInto(drains, box.bottom)

    hole cord_l { c = Circle(center=(0, 0), diameter=6 mm) }
    AlignCenterY(cord_l, box.left.outline)
    cord_l.c.center.x == box.left.outline.bb.left + 12 mm
    CutInto(cord_l, box.left)

    hole cord_r { c = Circle(center=(0, 0), diameter=6 mm) }
    AlignCenterY(cord_r, box.right.outline)
    cord_r.c.center.x == box.right.outline.bb.right - 12 mm
    CutInto(cord_r, box.right)

    drawing label {
        t = Text("NEST WOOL", position=(0, 0), size=8 mm)
    }
    label.t.position.x == box.front.outline.bb.center_x
    label.t.position.y == box.front.outline.bb.bottom + 145 mm
    CutInto(label, box.front)

    # the request's numbers
    assert box.front.outline.bb.width == 100 mm and box.front.outline.bb.height == 160 mm,
        "100 wide, 160 tall"
    assert box.left.outline.bb.height == 100 mm, "100 deep"
    assert len(front_l.g) == 15 and len(left_l.g) == 15, "15 openings per wall"
    assert front_l.bb.width == 2 * 26 mm + 16 mm and front_l.bb.height == 4 * 24 mm + 16 mm,
        "front pitch 26 across, 24 up"
    assert left_l.bb.width == 4 * 24 mm + 16 mm and left_l.bb.height == 2 * 26 mm + 16 mm,
        "side pitch 24 up, 26 across"
    assert front_l.bb.bottom - box.front.outline.bb.bottom == 25 mm, "lattice 25 mm up"
    assert box.right.outline.bb.right - right_l.bb.right ==
        box.front.outline.bb.top - front_l.bb.top, "side lattice level with the front's"
    assert drains.bb.width == 40 mm + 6 mm, "drains on a 40 mm square"
    assert box.right.outline.bb.right - cord_r.c.center.x == 12 mm, "cord hole 12 mm down"
    # the label clears the lattice and the top edge
    assert label.t.position.y - front_l.bb.top >= 4 mm, "label above the lattice"
    assert box.front.outline.bb.top - (label.t.position.y + 8 mm) >= 4 mm, "label below the top"
}
