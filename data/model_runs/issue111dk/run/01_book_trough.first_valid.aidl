# Request (home): a desk book trough for paperbacks, 6 mm birch ply. Two boards 300 mm long
# between the ends meet in a 90 degree V (the left board 120 mm wide, the right one 126 mm so
# it covers the left one's lower edge). Each board end is glued into an end panel by two
# 20 mm tabs through mortises. The two end panels are 200 mm wide and 140 mm tall, with a
# rounded top and a 120 mm wide, 15 mm high arched relief between two feet. "EMMA'S BOOKS"
# is engraved filled on the front end panel, in the V above the boards' meeting point.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
c45 = cos(45 deg)
board_len = 300 mm
w_left = 120 mm
w_right = 126 mm
foot_y = -40 mm      # the panels' bottom, below the V's inner meeting point (0, 0)

# One end panel; the V's inner faces meet at (0, 0). The mortises sit on the boards'
# mid-thickness lines: left board along 135 deg, right board along 45 deg.
def end_panel(name="") -> solid {
    body = Hull(Circle(center=(-82, 82), radius=18), Circle(center=(82, 82), radius=18),
                Rectangle(center=(0, -30), width=200, height=20))
    left_slots = tab_and_slot(part="slot", length=w_left, thickness=t, tabs=2, tab=20 mm,
                              screw=0, cx=-(w_left / 2 + t / 2) * c45,
                              cy=(w_left / 2 - t / 2) * c45, rotation=135 deg)
    right_slots = tab_and_slot(part="slot", length=w_right, thickness=t, tabs=2, tab=20 mm,
                               screw=0, cx=(w_right / 2 - t / 2) * c45,
                               cy=(w_right / 2 - 3 * t / 2) * c45, rotation=45 deg)
    hole relief {
        e = Ellipse(center=(0, -40), rx=60, ry=15)
    }
    if name != "" {
        drawing label {
            l1 = Text(f"{name}'S", position=(0, 66), size=11, font="sans:Bold", fill=true)
            l2 = Text("BOOKS", position=(0, 46), size=11, font="sans:Bold", fill=true)
        }
    }
}

# One board: its length along x, the tabs' tips at x = -t and x = board_len + t.
def board(w=120 mm) -> solid {
    body = Rectangle(bottom_left=(-t, 0), width=board_len + 2 * t, height=w)
    left_tabs = tab_and_slot(part="tab", length=w, thickness=t, tabs=2, tab=20 mm, screw=0,
                             cx=-t, cy=w / 2, rotation=90 deg)
    right_tabs = tab_and_slot(part="tab", length=w, thickness=t, tabs=2, tab=20 mm, screw=0,
                              cx=board_len + t, cy=w / 2, rotation=-90 deg)
}

assembly trough {
    front = end_panel(name="EMMA")
    back = end_panel()
    board_l = board(w=w_left)
    board_r = board(w=w_right)

    # flat on the sheet: the ends side by side, the boards above them
    RightOf(back, front, gap=10)
    AlignBottom(back, front)
    Above(board_l, front, gap=10)
    AlignLeft(board_l, front)
    Above(board_r, board_l, gap=10)
    AlignLeft(board_r, board_l)

    # in 3D: the trough runs along x, the front end's outer face at x = -t
    Place(front, position=(0, 0, -foot_y), face="left", up="up")
    Place(back, position=(board_len + t, 0, -foot_y), face="left", up="up")
    Place(board_l, position=(0, t * c45, -foot_y - t * c45), face=(0, -1, 1), up=(0, 1, 1))
    Place(board_r, position=(0, t * c45, -foot_y - t * c45), face=(0, -1, -1), up=(0, -1, 1))

    # the request's numbers
    assert board_l.body.bb.width == 300 mm + 2 * 6 mm, "300 mm between the ends"
    assert board_l.body.bb.height == 120 mm and board_r.body.bb.height == 126 mm, "board widths"
    assert front.body.bb.width == 200 mm and front.body.bb.height == 140 mm, "end panel 200 x 140"
    assert len(front.left_slots.slot) == 2 and len(board_l.left_tabs.gap) == 3, "two tabs per end"
    assert front.relief.e.bb.width == 120 mm, "relief 120 wide"
}
