# Request (home): a fireside log holder in 6 mm birch ply, glued and pressed together.
# Two end panels 320 mm wide x 380 mm tall; the top of each is a concave cradle, an arc
# that dips 90 mm at the middle; the bottom has an arched cut-out 220 mm wide and 80 mm tall
# that leaves two feet; a 100 x 30 mm hand-hold slot 60 mm below the cradle's lowest point;
# "LOGS" engraved filled in bold letters 20 mm tall between the base and the hand-hold.
# A base board 220 mm wide with 420 mm between the end panels sits 120 mm above the floor,
# with two 40 mm tabs through each end panel; two side rails 60 mm tall stand on the base
# board's long edges, each with one 30 mm tab through each end panel.

import "std/joints.aidl"

thickness 6 mm

param t = 6 mm, min = 3 mm, max = 12 mm   # ply thickness
W = 320 mm        # end panel width
H = 380 mm        # end panel height
DIP = 90 mm       # how far the cradle dips
INNER = 420 mm    # between the end panels
BOARD_W = 220 mm
BOARD_Y = 120 mm  # base board's underside above the floor
RAIL_H = 60 mm

def end_panel() -> solid {
    left = Line((-W / 2, 0), (-W / 2, H))
    cradle = Arc(start=(-W / 2, H), through=(0, H - DIP), end=(W / 2, H))
    right = Line((W / 2, H), (W / 2, 0))
    floor = Line((W / 2, 0), (-W / 2, 0))
    hole feet {
        low = Rectangle(center=(0, 20), width=220, height=40)
        arch = Ellipse(center=(0, 40), rx=110, ry=40)
    }
    hole handhold {
        s = Slot(center=(0, H - DIP - 60), length=100, width=30)
    }
    # mortises for the base board (its mid-plane at BOARD_Y + t / 2)
    board_slots = tab_and_slot(part="slot", length=BOARD_W, thickness=t, tabs=2, tab=40,
                               screw=0, cx=0, cy=BOARD_Y + t / 2)
    # mortises for the side rails, standing on the board's long edges
    rail_l = tab_and_slot(part="slot", length=RAIL_H, thickness=t, tabs=1, tab=30, screw=0,
                          cx=-(BOARD_W / 2 + t / 2), cy=BOARD_Y + t + RAIL_H / 2,
                          rotation=90 deg)
    rail_r = tab_and_slot(part="slot", length=RAIL_H, thickness=t, tabs=1, tab=30, screw=0,
                          cx=BOARD_W / 2 + t / 2, cy=BOARD_Y + t + RAIL_H / 2,
                          rotation=90 deg)
    drawing word {
        w = Text("LOGS", (0, BOARD_Y + t + 30), size=20, font="sans:Bold", fill=true)
    }
}

def rail(width=60 mm, tabs=1, tab=30 mm) -> solid {
    body = Rectangle(center=(0, 0), width=INNER + 2 * t, height=width)
    right_end = tab_and_slot(part="tab", length=width, thickness=t, tabs=tabs, tab=tab,
                             screw=0, cx=INNER / 2 + t, cy=0, rotation=-90 deg)
    left_end = tab_and_slot(part="tab", length=width, thickness=t, tabs=tabs, tab=tab,
                            screw=0, cx=-(INNER / 2 + t), cy=0, rotation=90 deg)
}

assembly log_holder {
    end_a = end_panel()
    end_b = end_panel()
    board = rail(width=BOARD_W, tabs=2, tab=40 mm)
    side_a = rail(width=RAIL_H)
    side_b = rail(width=RAIL_H)

    end_a.bb.center == (-180, 190)
    end_b.bb.center == (180, 190)
    board.bb.center == (0, -140)
    side_a.bb.center == (0, -300)
    side_b.bb.center == (0, -380)

    # the request's numbers
    assert end_a.bb.width == 320 mm, "end panel 320 wide"
    assert end_a.bb.height == 380 mm, "end panel 380 tall"
    assert end_a.cradle.through.y - end_a.floor.start.y == 380 mm - 90 mm, "cradle dips 90"
    assert end_a.feet.bb.width == 220 mm and end_a.feet.bb.height == 80 mm, "arch 220 x 80"
    assert (end_a.cradle.through.y - end_a.handhold.s.center.y) == 60 mm, "hand-hold 60 below"
    assert board.body.width == 420 mm + 2 * t, "420 between the ends, tabs through"
    assert board.body.height == 220 mm, "board 220 wide"
    assert side_a.body.height == 60 mm, "rails 60 tall"
    assert len(end_a.board_slots.slot) == 2 and len(end_a.rail_l.slot) == 1, "tab counts"
    # the rails' mortises clear the hand-hold and the board's mortises clear the arch
    assert end_a.rail_l.bb.top < end_a.handhold.bb.bottom, "rail below the hand-hold"
    assert end_a.board_slots.bb.bottom - end_a.feet.bb.top >= 30 mm, "wood under the board"
}
