# Request: a child's tree swing seat from 12 mm exterior birch plywood. The seat is
# 450 x 200 mm with R30 corners, four 16 mm rope holes centred 35 mm in from both the
# ends and the long edges. Two stiffening cleats stand on edge under the seat, across it,
# their centre lines 100 mm in from each end: each cleat 180 mm long, reaching 50 mm below
# the seat, its bottom corners rounded R10, glued up into the seat with two 40 mm tenons
# through mortises. The child's name "ROSIE" is engraved (filled, bold, 40 mm capitals)
# in the middle of the seat.

import "std/joints.aidl"

units mm
t = 12 mm
thickness t
kerf 0.2 mm

seat_w = 450 mm
seat_d = 200 mm
cleat_in = 100 mm
cleat_len = 180 mm
cleat_drop = 50 mm

def cleat() -> solid {
    body = RoundedRectangle(bottom_left=(-cleat_len / 2, 0), width=cleat_len, height=cleat_drop + t,
                            corner_radii=[0, 0, 10, 10])
    tenons = tab_and_slot(part="tab", length=cleat_len, thickness=t, tabs=2, tab=40 mm, screw=0,
                          cx=0 mm, cy=cleat_drop + t)
}

assembly swing {
    solid seat {
        board = RoundedRectangle(center=(0, 0), width=seat_w, height=seat_d, corner_radius=30)
        hole rope {
            c = Circle(center=(0, 0), diameter=16)
        }
        ropes = CornerPattern(rope, board, inset=35)
        left_mortise = tab_and_slot(part="slot", length=cleat_len, thickness=t, tabs=2, tab=40 mm,
                                    screw=0, rotation=90 deg, cx=-seat_w / 2 + cleat_in, cy=0 mm)
        right_mortise = tab_and_slot(part="slot", length=cleat_len, thickness=t, tabs=2, tab=40 mm,
                                     screw=0, rotation=90 deg, cx=seat_w / 2 - cleat_in, cy=0 mm)
        drawing name {
            word = Text("ROSIE", position=(0, 0), size=40, font="sans:Bold", valign="middle",
                        fill=true)
        }
        Fixed(board)

        assert board.width == 450 mm and board.height == 200 mm, "seat 450 x 200"
        assert len(ropes) == 4, "four rope holes"
        assert rope.c.diameter == 16 mm, "16 mm rope holes"
        assert ropes[0].c.center.x - board.bb.left == 35 mm, "rope holes 35 mm in from the ends"
        assert ropes[0].c.center.y - board.bb.bottom == 35 mm, "rope holes 35 mm in from the long edges"
        assert ropes[2].c.center.x == board.bb.right - 35 mm and ropes[2].c.center.y == board.bb.top - 35 mm,
            "the opposite hole likewise"
        assert left_mortise.cx - board.bb.left == 100 mm, "left cleat 100 mm in"
        assert board.bb.right - right_mortise.cx == 100 mm, "right cleat 100 mm in"
        assert distance(name, left_mortise) >= 10 mm and distance(name, right_mortise) >= 10 mm,
            "the name clear of the mortises"
    }
    left_cleat = cleat()
    right_cleat = cleat()
    Below(left_cleat, seat, gap=10)
    AlignLeft(left_cleat, seat)
    RightOf(right_cleat, left_cleat, gap=10)
    AlignTop(right_cleat, left_cleat)

    assert left_cleat.body.width == 180 mm, "cleats 180 mm long"
    assert left_cleat.body.height - t == 50 mm, "cleats reach 50 mm below the seat"
    assert len(left_cleat.tenons.gap) == 3, "two tenons"

    # 3D: the seat flat on top of the cleats, the cleats on edge across it under the mortises
    Place(seat, position=(0, 0, cleat_drop))
    Place(left_cleat, position=(-seat_w / 2 + cleat_in - t / 2, 0, 0), face="right", up="up")
    Place(right_cleat, position=(seat_w / 2 - cleat_in - t / 2, 0, 0), face="right", up="up")
}
