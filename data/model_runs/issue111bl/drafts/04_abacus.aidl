# Request (toys): a 10-row counting frame (abacus) for a child, 6 mm birch ply, strung with bought
# 8 mm dowels and 20 mm wooden beads (ten per row). Two uprights 80 mm wide with a round
# (semicircular) top, each holding ten dowel holes 8.2 mm across on its centre line, 22 mm apart,
# the lowest 30 mm above the base; the uprights stand 240 mm apart inside (room for ten beads and
# 40 mm to slide). Base 300 x 110 mm, corners r8, the uprights 10 mm behind its middle; each upright
# glued in with two 15 mm tabs (slots 0.15 mm clearance). Row numbers 1 (top) to 10 engraved 6 mm
# tall beside the holes on the left upright, 28 mm left of them; "MAYA'S ABACUS" engraved 8 mm tall
# on the base's front strip.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
rows = 10
pitch = 22 mm
first_row = 30 mm
hole_d = 8.2 mm
up_w = 80 mm
inside = 240 mm
up_y = 10 mm
top_row_y = first_row + (rows - 1) * pitch

def upright(numbered=false) -> solid {
    body = Rectangle(bottom_left=(-up_w / 2, -t), width=up_w, height=top_row_y + t)
    arch = Circle(center=(0, top_row_y), radius=up_w / 2)
    for i in range(rows) {
        hole dowel { c = Circle(center=(0, first_row + i * pitch), diameter=hole_d) }
    }
    tabs = tab_and_slot(part="tab", length=up_w, thickness=t, tabs=2, tab=15, screw=0,
                        rotation=180, cx=0, cy=-t)
    if numbered {
        drawing nums {
            for i in range(rows) {
                n = Text(str(rows - i), position=(-28, first_row + i * pitch), size=6,
                         valign="middle")
            }
        }
    }
}

solid base_board() {
    body = RoundedRectangle(center=(0, 0), width=300, height=110, corner_radius=8)
    left = tab_and_slot(part="slot", length=up_w, thickness=t, tabs=2, tab=15, screw=0,
                        clearance=0.15, rotation=90, cx=-(inside + t) / 2, cy=up_y)
    right = tab_and_slot(part="slot", length=up_w, thickness=t, tabs=2, tab=15, screw=0,
                         clearance=0.15, rotation=90, cx=(inside + t) / 2, cy=up_y)
    drawing name {
        txt = Text("MAYA'S ABACUS", position=(0, (-55 + up_y - up_w / 2) / 2), size=8,
                   valign="middle")
    }
}

assembly abacus {
    base = base_board()
    left_up = upright(numbered=true)
    right_up = upright()

    Above(left_up, base, gap=5)
    AlignLeft(left_up, base)
    RightOf(right_up, left_up, gap=5)
    AlignBottom(right_up, left_up)

    Place(base, position=(0, 0, 0))
    Place(left_up, rotation=(90 deg, 0, 90 deg), position=(-(inside + t) / 2 - t / 2, up_y, t))
    Place(right_up, rotation=(90 deg, 0, 90 deg), position=((inside + t) / 2 - t / 2, up_y, t))

    # the request's numbers
    assert len(left_up.dowel) == 10, "ten rows"
    assert left_up.dowel[1].c.center.y - left_up.dowel[0].c.center.y == 22 mm, "22 apart"
    assert left_up.dowel[0].c.center.y - left_up.tabs.gap[0].bb.top == 30 mm, "lowest 30 up"
    assert left_up.dowel[0].c.diameter == 8.2 mm, "8.2 holes"
    assert left_up.body.bb.width == 80 mm, "80 wide"
    assert base.right.bb.center_x - base.left.bb.center_x - t == 240 mm, "240 inside"
    assert base.body.bb.width == 300 mm and base.body.bb.height == 110 mm, "base size"
    assert len(left_up.nums.n) == 10, "ten numbers"
    assert left_up.dowel[0].c.center.x - left_up.nums.n[0].position.x == 28 mm, "numbers 28 left"
    assert base.name.bb.top < base.left.bb.bottom, "name in front of the uprights"
}
