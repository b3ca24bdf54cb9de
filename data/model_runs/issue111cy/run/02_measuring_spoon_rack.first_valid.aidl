# Request (kitchen): a wall rack for a set of 5 measuring spoons, 4 mm birch ply.
# Backboard 280 x 150 mm, 8 mm corner radius, hung on two screws by keyholes (9 mm head,
# 4.5 mm slot, 10 mm long, opening upward) 200 mm apart, their heads 20 mm below the top edge.
# A shelf sticks out 45 mm from the board's face, its underside 70 mm above the board's bottom
# edge, glued into the board by 3 tabs 20 mm wide. Under each end of the shelf, 12 mm in from
# its end (to the cheek's middle), a quarter-round cheek of 45 mm radius, tabbed (one 20 mm tab
# each edge) into both board and shelf. In the shelf, 5 closed slots 18 x 5 mm on a 45 mm
# pitch, centred along the shelf, halfway across its depth: each spoon's handle drops through
# and its bowl rests on the shelf. Above each slot, on the board, its size engraved in 6 mm
# letters with the baseline 15 mm above the shelf's top: 1 TBSP, 1 TSP, 1/2 TSP, 1/4 TSP, 1/8 TSP.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 4 mm

T = 4 mm
sizes = ["1 TBSP", "1 TSP", "1/2 TSP", "1/4 TSP", "1/8 TSP"]
pitch = 45 mm
depth = 45 mm          # shelf, from the board's face
cheek_r = 45 mm
cheek_x = 128 mm       # cheek's middle from the centre line (140 - 12)

# a quarter-round cheek: in its frame the board's back face is x = 0 and the shelf's top is
# y = 0; tabs run into both
def cheek() -> solid {
    quarter = Sector(center=(-T, -T), radius=cheek_r, start_angle=180 deg, end_angle=270 deg)
    top_strip = Rectangle(bottom_left=(-T - cheek_r, -T), width=cheek_r, height=T)
    back_strip = Rectangle(bottom_left=(-T, -T - cheek_r), width=T, height=cheek_r)
    top_tab = tab_and_slot(part="tab", length=cheek_r, thickness=T, tabs=1, tab=20 mm,
                           screw=0, rotation=0 deg, cx=-T - cheek_r / 2, cy=0 mm)
    back_tab = tab_and_slot(part="tab", length=cheek_r, thickness=T, tabs=1, tab=20 mm,
                            screw=0, rotation=-90 deg, cx=0 mm, cy=-T - cheek_r / 2)
}

assembly spoon_rack {
    # board frame: centre (0, 0); bottom edge y = -75; shelf underside y = -5
    solid board {
        body = RoundedRectangle(center=(0, 0), width=280 mm, height=150 mm, corner_radius=8 mm)
        kh_left = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg,
                          cx=-100 mm, cy=55 mm)
        kh_right = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg,
                           cx=100 mm, cy=55 mm)
        shelf_mortise = tab_and_slot(part="slot", length=280 mm, thickness=T, tabs=3,
                                     tab=20 mm, screw=0, cx=0 mm, cy=-5 mm + T / 2)
        cheek_mortise_l = tab_and_slot(part="slot", length=cheek_r, thickness=T, tabs=1,
                                       tab=20 mm, screw=0, rotation=90 deg,
                                       cx=-cheek_x, cy=-5 mm - cheek_r / 2)
        cheek_mortise_r = tab_and_slot(part="slot", length=cheek_r, thickness=T, tabs=1,
                                       tab=20 mm, screw=0, rotation=90 deg,
                                       cx=cheek_x, cy=-5 mm - cheek_r / 2)
        drawing labels {
            for i in range(5) {
                t = Text(sizes[i], position=((i - 2) * pitch, -5 mm + T + 15 mm), size=6 mm)
            }
        }
    }

    # shelf frame: the tabs' tips (the board's back face) on y = 0, the front edge y = -49
    solid shelf {
        body = Rectangle(bottom_left=(-140 mm, -T - depth), width=280 mm, height=T + depth)
        back_tabs = tab_and_slot(part="tab", length=280 mm, thickness=T, tabs=3, tab=20 mm,
                                 screw=0, cx=0 mm, cy=0 mm)
        hole spoon_slots {
            for i in range(5) {
                s = Slot(center=((i - 2) * pitch, -T - depth / 2), length=18 mm, width=5 mm)
            }
        }
        cheek_mortise_l = tab_and_slot(part="slot", length=cheek_r, thickness=T, tabs=1,
                                       tab=20 mm, screw=0, rotation=90 deg,
                                       cx=-cheek_x, cy=-T - cheek_r / 2)
        cheek_mortise_r = tab_and_slot(part="slot", length=cheek_r, thickness=T, tabs=1,
                                       tab=20 mm, screw=0, rotation=90 deg,
                                       cx=cheek_x, cy=-T - cheek_r / 2)
    }

    cheek_l = cheek()
    cheek_r_part = cheek()

    # laid out flat for cutting
    Below(shelf, board, gap=10 mm)
    AlignCenterX(shelf, board)
    Below(cheek_l, shelf, gap=10 mm)
    Below(cheek_r_part, shelf, gap=10 mm)
    AlignLeft(cheek_l, shelf)
    AlignRight(cheek_r_part, shelf)

    # in 3D: the board stands with its back face on y = 0, bottom edge on z = 0
    Place(board, position=(0, 0, 75 mm), face="front", up="up")
    Place(shelf, position=(0, 0, 70 mm), face="up", up="back")
    Place(cheek_l, position=(-cheek_x - T / 2, 0, 70 mm + T), face="right", up="up")
    Place(cheek_r_part, position=(cheek_x - T / 2, 0, 70 mm + T), face="right", up="up")

    # the request's numbers
    assert board.body.bb.width == 280 mm and board.body.bb.height == 150 mm, "board 280 x 150"
    assert board.kh_right.head_hole.center.x - board.kh_left.head_hole.center.x == 200 mm,
        "keyholes 200 apart"
    assert board.body.bb.top - board.kh_left.head_hole.center.y == 20 mm, "20 below the top"
    assert board.kh_left.head == 9 mm and board.kh_left.slot_width == 4.5 mm, "keyhole sizes"
    assert board.shelf_mortise.slot[0].bb.bottom - board.body.bb.bottom == 70 mm,
        "shelf underside 70 mm up"
    assert len(board.shelf_mortise.slot) == 3, "3 tabs"
    assert shelf.body.bb.height - T == 45 mm, "shelf sticks out 45 mm"
    assert len(shelf.spoon_slots.s) == 5, "5 spoon slots"
    assert shelf.spoon_slots.s[1].center.x - shelf.spoon_slots.s[0].center.x == 45 mm,
        "45 mm pitch"
    assert abs(shelf.spoon_slots.bb.center_x - shelf.body.bb.center_x) < 0.01 mm,
        "slots centred along the shelf"
    assert shelf.body.bb.right - shelf.cheek_mortise_r.slot[0].bb.center_x == 12 mm,
        "cheek 12 mm in"
    assert cheek_l.quarter.radius == 45 mm, "45 mm cheeks"
    assert board.labels.t[0].position.y - board.shelf_mortise.slot[0].bb.top == 15 mm,
        "labels 15 mm above the shelf's top"
    assert board.labels.t[2].size == 6 mm, "6 mm letters"
}
