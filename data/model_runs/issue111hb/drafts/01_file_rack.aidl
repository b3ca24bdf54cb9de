# Request (workshop): a wall rack for my six engineer's files, cut from 6 mm birch ply.
# A back board 320 x 110 mm hangs on two screws through keyholes (8 mm head, 4 mm slot)
# 40 mm in from each end with the head 20 mm below the top edge. A shelf 320 mm wide
# standing 70 mm out from the back is glued into the back with 3 tabs 30 mm wide, its
# middle 35 mm below the back's top edge. The shelf has 6 slots, 9 mm wide, 45 mm apart,
# centred 30 mm out from the back, long enough for each file's blade (rasp 30, flat 26,
# half-round 22, triangular 16, square 12, round 12 mm), the file's name engraved in
# front of each slot. Two triangular brackets 60 x 60 mm under the shelf ends, centred
# 9 mm in from each end, each with one 30 mm tab into the shelf and one into the back.

units mm
thickness 6 mm

import "std/joints.aidl"
import "std/plates.aidl"

t = 6 mm            # ply thickness
W = 320 mm          # rack width
back_h = 110 mm
shelf_d = 70 mm     # shelf depth in front of the back
shelf_drop = 35 mm  # back's top edge to the shelf's middle
br = 60 mm          # bracket legs
br_x = W / 2 - 9 mm # bracket centre line from the middle
pitch = 45 mm
names = ["RASP", "FLAT", "HALF RD", "TRI", "SQUARE", "ROUND"]
lens = [30 mm, 26 mm, 22 mm, 16 mm, 12 mm, 12 mm]

def bracket() -> solid {
    # flat: top edge (into the shelf) along y = 0, back edge (into the back) along x = 0
    tri = Polygon([(t, 0), (t + br, 0), (0, -(t + br)), (0, -t), (t, -t)])
    top_j = tab_and_slot(part="tab", length=br, thickness=t, tabs=1, tab=30 mm, screw=0,
                         cx=t + br / 2, cy=0)
    back_j = tab_and_slot(part="tab", length=br, thickness=t, tabs=1, tab=30 mm, screw=0,
                          rotation=90 deg, cx=0, cy=-(t + br / 2))
}

assembly file_rack {
    solid back {
        board = Rectangle(center=(0, 0), width=W, height=back_h)
        # shelf mortises: the shelf's middle 35 mm below the top edge
        shelf_m = tab_and_slot(part="slot", length=W, thickness=t, tabs=3, tab=30 mm, screw=0,
                               cx=0, cy=back_h / 2 - shelf_drop)
        # bracket mortises: below the shelf's underside, vertical
        left_m = tab_and_slot(part="slot", length=br, thickness=t, tabs=1, tab=30 mm, screw=0,
                              rotation=90 deg, cx=-br_x,
                              cy=back_h / 2 - shelf_drop - t / 2 - br / 2)
        right_m = tab_and_slot(part="slot", length=br, thickness=t, tabs=1, tab=30 mm, screw=0,
                               rotation=90 deg, cx=br_x,
                               cy=back_h / 2 - shelf_drop - t / 2 - br / 2)
        hang_l = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=-W / 2 + 40 mm,
                         cy=back_h / 2 - 20 mm)
        hang_r = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=W / 2 - 40 mm,
                         cy=back_h / 2 - 20 mm)
        Fixed(board)
        assert board.width == 320 mm, "back 320 wide"
        assert board.height == 110 mm, "back 110 high"
        assert hang_l.head_hole.center.x - board.bb.left == 40 mm, "keyhole 40 in"
        assert board.bb.right - hang_r.head_hole.center.x == 40 mm, "keyhole 40 in"
        assert board.bb.top - hang_l.head_hole.center.y == 20 mm, "keyhole 20 down"
    }

    solid shelf {
        # flat: the back edge (tab tips) on top, the front edge at the bottom
        plate = Rectangle(center=(0, 0), width=W, height=shelf_d + t)
        tabs = tab_and_slot(part="tab", length=W, thickness=t, tabs=3, tab=30 mm, screw=0,
                            cx=0, cy=(shelf_d + t) / 2)
        left_m = tab_and_slot(part="slot", length=br, thickness=t, tabs=1, tab=30 mm, screw=0,
                              rotation=90 deg, cx=-br_x, cy=(shelf_d + t) / 2 - t - br / 2)
        right_m = tab_and_slot(part="slot", length=br, thickness=t, tabs=1, tab=30 mm, screw=0,
                               rotation=90 deg, cx=br_x, cy=(shelf_d + t) / 2 - t - br / 2)
        hole blades {
            for i in range(6) {
                s = Slot(center=((i - 2.5) * pitch, (shelf_d + t) / 2 - t - 30 mm),
                         length=lens[i], width=9 mm)
            }
        }
        drawing labels {
            for i in range(6) {
                n = Text(names[i], position=((i - 2.5) * pitch, -(shelf_d + t) / 2 + 10 mm),
                         size=6, valign="middle")
            }
        }
        Fixed(plate)
        assert len(blades.s) == 6, "six slots"
        assert blades.s[1].center.x - blades.s[0].center.x == 45 mm, "45 mm apart"
        assert plate.bb.top - t - blades.s[0].center.y == 30 mm, "30 mm out from the back"
        assert plate.height - t == 70 mm, "shelf stands 70 out"
        assert blades.s[0].length == 30 mm and blades.s[5].length == 12 mm, "blade lengths"
    }

    left_br = bracket()
    right_br = bracket()

    # lay the parts out flat: shelf under the back, brackets beside it
    Below(shelf, back, gap=10 mm)
    AlignLeft(shelf, back)
    RightOf(left_br, shelf, gap=10 mm)
    AlignTop(left_br, shelf)
    RightOf(right_br, left_br, gap=10 mm)
    AlignTop(right_br, shelf)
}
