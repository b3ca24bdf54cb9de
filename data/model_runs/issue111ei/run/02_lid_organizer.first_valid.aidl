# Request (kitchen): a rack for the plastic food-box lids in my kitchen drawer, so they stand
# on edge sorted by size. 3 mm ply. A base 300 x 160 with R6 corners. Six boards stand across
# it, 140 long (10 mm short of the base front and back), the outer faces of the two end boards
# 6 mm in from the base ends, the boards evenly spaced so there are five 54 mm clear
# compartments. The end boards stand 110 tall with a 70 x 20 hand hole centred 22 mm under
# their top; the four inner dividers stand 90 tall with an R18 finger scoop in the middle of
# the top (its edges rounded R4). All top corners R12. Each board is glued into the base with
# two 20 mm tenons into mortises. Engraved (plain strokes, 5 mm) along the base front in front
# of each compartment: SMALL, MEDIUM, LARGE, ROUND, SQUARE.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
base_w = 300 mm
base_d = 160 mm
board_len = 140 mm
clear = 54 mm
pitch = clear + t
end_in = 6 mm
x0 = -base_w / 2 + end_in + t / 2           # centre plane of the first board
names = ["SMALL", "MEDIUM", "LARGE", "ROUND", "SQUARE"]

def board(h=90 mm, scoop=true) -> solid {
    # drawn on its side as it stands: x along the board, y up; the tenon tips at y = -3
    body = Rectangle(bottom_left=(-board_len / 2, -t), width=board_len, height=h + t)
    tenons = tab_and_slot(part="tab", length=board_len, thickness=t, tabs=2, tab=20 mm,
                          screw=0, rotation=180 deg, cx=0 mm, cy=-t)
    Fillet([body.top_left, body.top_right], 12)
    if scoop {
        hole grip { c = Circle(center=(0, h), radius=18) }
        Fillet([body.top, grip.c], 4)
    } else {
        hole handle { s = Slot(center=(0, h - 22 mm), length=70, width=20) }
    }
}

assembly lid_organizer {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=base_w, height=base_d, corner_radius=6)
        for i in range(6) {
            m = tab_and_slot(part="slot", length=board_len, thickness=t, tabs=2, tab=20 mm,
                             screw=0, rotation=90 deg, cx=x0 + i * pitch, cy=0 mm)
        }
        drawing labels {
            for i in range(5) {
                w = Text(names[i], position=(x0 + i * pitch + pitch / 2, -base_d / 2 + 5 mm),
                         size=5, valign="middle")
            }
        }
    }

    for i in range(6) {
        b = board(h=110 mm if i == 0 or i == 5 else 90 mm, scoop=not (i == 0 or i == 5))
        Place(b, position=(x0 + i * pitch - t / 2, 0, t), face="right", up="up")
    }
    Place(base, position=(0, 0, 0), face="up")

    # laid out flat: the boards in a row above the base
    Above(b[0], base, gap=6)
    AlignLeft(b[0], base)
    for i in range(1, 6) {
        RightOf(b[i], b[i - 1], gap=6)
        AlignBottom(b[i], b[0])
    }

    # the request's numbers
    assert len(b) == 6, "six boards"
    assert base.m[1].slot[0].bb.center_x - base.m[0].slot[0].bb.center_x - t == 54 mm,
        "54 mm clear compartments"
    assert base.m[0].slot[0].bb.left - base.plate.bb.left == 6 mm, "end boards 6 in"
    assert base.plate.bb.right - base.m[5].slot[0].bb.right == 6 mm, "end boards 6 in"
    assert b[0].body.bb.height - t == 110 mm and b[1].body.bb.height - t == 90 mm, "board heights"
    assert base.plate.bb.height - b[1].body.bb.width == 20 mm, "boards 10 short front and back"
    assert distance(base.labels, base.m[0]) >= 1 mm, "labels clear of the mortises"
}
