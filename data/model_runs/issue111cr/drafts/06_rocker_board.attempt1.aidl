# Request: a flat-pack rocker balance board for a child's balance training, 9 mm birch ply.
# Deck 600 x 300 mm with 30 mm corners, a 100 x 28 mm hand slot across each end (centres 270 mm
# from the middle), engraved grip lines in two foot zones (15 lines 10 mm apart each, x from
# 80 to 220 mm either side, 140 mm long across the deck) and "BALANCE" filled-engraved 24 mm high
# (bold sans) in the middle. Two rockers 500 mm long, 180 mm apart (centre to centre), their
# bottoms one arc from 30 mm high at the ends to 80 mm at the middle; each screwed to the deck by
# 3 tabs 40 mm wide with M4 captive-nut T-slots, the deck's screw holes countersunk (8.5 mm).
# Two spreaders 220 x 30 mm under the deck, 215 mm either side of the middle, cross-halved
# into both rockers (15 mm deep each way). Five parts.

import "std/joints.aidl"

units mm
thickness 9 mm

T = 9 mm
ROCKER_Y = 90 mm
SPREAD_X = 215 mm

def rocker() -> solid {
    # y = 0 is the deck's underside; the tabs stand up to y = T through the deck
    top = Line((-250, T), (250, T))
    right = Line((250, T), (250, -30))
    arc = Arc(start=(250, -30), through=(0, -80), end=(-250, -30))
    left = Line((-250, -30), (-250, T))
    joint = tab_and_slot(part="tab", length=500 mm, thickness=T, tabs=3, tab=40 mm, screw=4,
                         cx=0 mm, cy=T)
    h_left = cross_halving(depth=15 mm, thickness=T, cx=-SPREAD_X, cy=0 mm)
    h_right = cross_halving(depth=15 mm, thickness=T, cx=SPREAD_X, cy=0 mm)
}

def spreader() -> solid {
    body = Rectangle(bottom_left=(-110, -30), width=220, height=30)
    h_a = cross_halving(depth=15 mm, thickness=T, rotation=180 deg, cx=-ROCKER_Y, cy=-30 mm)
    h_b = cross_halving(depth=15 mm, thickness=T, rotation=180 deg, cx=ROCKER_Y, cy=-30 mm)
}

assembly rocker_board {
    solid deck {
        body = RoundedRectangle(center=(0, 0), width=600, height=300, corner_radius=30)
        j_back = tab_and_slot(part="slot", length=500 mm, thickness=T, tabs=3, tab=40 mm,
                              screw=4, cx=0 mm, cy=ROCKER_Y)
        j_front = tab_and_slot(part="slot", length=500 mm, thickness=T, tabs=3, tab=40 mm,
                               screw=4, cx=0 mm, cy=-ROCKER_Y)
        Countersink([j_back.bolt, j_front.bolt], diameter=8.5 mm)
        hole handles {
            l = Slot(center=(-270, 0), length=100, width=28, rotation=90 deg)
            r = Slot(center=(270, 0), length=100, width=28, rotation=90 deg)
        }
        drawing grip {
            for i in range(15) {
                gl = Line((-80 - i * 10, -70), (-80 - i * 10, 70))
                gr = Line((80 + i * 10, -70), (80 + i * 10, 70))
            }
            word = Text("BALANCE", position=(0, 0), size=24, font="sans:Bold", valign="middle",
                        fill=true)
        }
    }
    front_rocker = rocker()
    back_rocker = rocker()
    left_spreader = spreader()
    right_spreader = spreader()

    # flat on the sheet
    Below(front_rocker, deck, gap=8 mm)
    AlignLeft(front_rocker, deck)
    Below(back_rocker, front_rocker, gap=8 mm)
    AlignLeft(back_rocker, front_rocker)
    RightOf(left_spreader, front_rocker, gap=8 mm)
    AlignTop(left_spreader, front_rocker)
    Below(right_spreader, left_spreader, gap=8 mm)
    AlignLeft(right_spreader, left_spreader)

    # assembled: rockers on the floor, deck on their tabs, spreaders across them
    Place(deck, position=(0, 0, 80))
    Place(front_rocker, position=(0, -ROCKER_Y + T / 2, 80), face="front", up="up")
    Place(back_rocker, position=(0, ROCKER_Y + T / 2, 80), face="front", up="up")
    Place(left_spreader, position=(-SPREAD_X - T / 2, 0, 80), face="right", up="up")
    Place(right_spreader, position=(SPREAD_X - T / 2, 0, 80), face="right", up="up")

    # the request's numbers
    assert deck.body.bb.width == 600 mm and deck.body.bb.height == 300 mm, "deck 600 x 300"
    assert deck.handles.r.length == 100 mm and deck.handles.r.width == 28 mm, "hand slots"
    assert deck.handles.r.center.x - deck.body.bb.center_x == 270 mm, "slots 270 from the middle"
    assert len(deck.grip.gl) == 15 and len(deck.grip.gr) == 15, "15 grip lines per zone"
    assert front_rocker.top.length == 500 mm, "rockers 500 long"
    assert deck.j_back.slot[0].bb.center_y - deck.j_front.slot[0].bb.center_y == 180 mm,
        "rockers 180 mm apart"
    assert front_rocker.joint.bb.bottom - front_rocker.arc.bb.bottom == 80 mm, "80 at the middle"
    assert front_rocker.joint.bb.bottom - front_rocker.right.end.y == 30 mm, "30 at the ends"
    assert len(front_rocker.joint.gap) - 1 == 3, "3 tabs"
    assert left_spreader.body.bb.width == 220 mm and left_spreader.body.bb.height == 30 mm,
        "spreaders 220 x 30"
    assert front_rocker.h_right.cut.bb.center_x - front_rocker.h_left.cut.bb.center_x == 430 mm,
        "spreaders 215 mm either side"
}
