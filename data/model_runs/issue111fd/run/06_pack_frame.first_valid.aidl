# Request (camping): a plywood pack frame (a freighter frame for carrying a dry bag, firewood or
# a water can), in 6 mm marine ply. Two side rails 600 mm tall, seen from the side: a straight
# front (load) edge, a back edge curved for the wearer's back (bulging to 70 mm deep at 150 mm
# up, 50 mm at the top), a rounded top, and at the bottom a foot 40 mm high running 180 mm
# forward under the load, braced by a curved gusset up to the front edge at 250 mm. Three
# crossbars 60 mm high, 320 mm across the outside of the rails, pass through the rails on 40 mm
# through-tenons 12 mm behind the front edge (their middles 120, 330 and 540 mm up). The load
# shelf, 180 mm deep, 320 across, sits in the feet on two 50 mm tenons each side, its middle
# 20 mm up. Strap slots 40 x 8 mm: shoulder straps in the top bar 120 apart, lashing in the
# middle bar 200 apart, hip belt in the bottom bar 260 apart; four 30 x 6 lashing slots along
# the shelf's front edge; four 10 mm cord holes along each rail between the bars. "TRAIL"
# engraved on the middle bar in filled letters 20 mm high.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
RAIL_H = 600 mm
FOOT = 180 mm
FOOT_H = 40 mm
BAR_H = 60 mm
ACROSS = 320 mm
BAR_X = 12 mm         # the bars' middle behind the rail's front edge
BARS = [120 mm, 330 mm, 540 mm]
SHELF_Y = 20 mm
STRAPS = [120 mm, 200 mm, 260 mm]

def rail_part() -> solid {
    body = Spline([(-FOOT, 0), (55, 0), (70, 150), (55, 330), (50, 560), (35, 598), (12, 600),
                   (0, 580), (0, 250), (-60, 95), (-FOOT, FOOT_H)],
                  closed=true, corners=[0, 1, 7, 8, 10])
    for y in BARS {
        bar_slot = tab_and_slot(part="slot", length=BAR_H, thickness=T, tabs=1, tab=40 mm,
                                screw=0, rotation=90 deg, cx=BAR_X, cy=y)
    }
    shelf_slot = tab_and_slot(part="slot", length=FOOT, thickness=T, tabs=2, tab=50 mm, screw=0,
                              cx=-FOOT / 2, cy=SHELF_Y)
    hole cords {
        for y in [220, 280, 420, 480] {
            c = Circle(center=(30, y), diameter=10)
        }
    }
}

def bar_part(strap=120 mm, word="") -> solid {
    body = Rectangle(center=(0, 0), width=ACROSS, height=BAR_H)
    left = tab_and_slot(part="tab", length=BAR_H, thickness=T, tabs=1, tab=40 mm, screw=0,
                        rotation=90 deg, cx=-ACROSS / 2, cy=0)
    right = tab_and_slot(part="tab", length=BAR_H, thickness=T, tabs=1, tab=40 mm, screw=0,
                         rotation=-90 deg, cx=ACROSS / 2, cy=0)
    hole straps {
        for s in [-1, 1] {
            st = Slot(center=(s * strap / 2, 0), length=40, width=8, rotation=90 deg)
        }
    }
    if word != "" {
        drawing mark {
            w = Text(word, position=(0, 0), size=20, font="sans:Bold", valign="middle", fill=true)
        }
    }
}

def shelf_part() -> solid {
    body = Rectangle(center=(0, 0), width=ACROSS, height=FOOT)
    left = tab_and_slot(part="tab", length=FOOT, thickness=T, tabs=2, tab=50 mm, screw=0,
                        rotation=90 deg, cx=-ACROSS / 2, cy=0)
    right = tab_and_slot(part="tab", length=FOOT, thickness=T, tabs=2, tab=50 mm, screw=0,
                         rotation=-90 deg, cx=ACROSS / 2, cy=0)
    hole lashing {
        for i in range(4) {
            s = Slot(center=(-105 + i * 70, -FOOT / 2 + 15), length=30, width=6)
        }
    }
}

assembly pack_frame {
    for i in range(2) {
        rail = rail_part()
        # rails on edge, the load side toward -y, the outer faces at x = -160 and +160
        Place(rail, position=(-ACROSS / 2 + i * (ACROSS - T), 0, 0), face="right", up="up")
    }
    top_bar = bar_part(strap=STRAPS[0])
    mid_bar = bar_part(strap=STRAPS[1], word="TRAIL")
    low_bar = bar_part(strap=STRAPS[2])
    Place(top_bar, position=(0, BAR_X + T / 2, BARS[2]), face="front", up="up")
    Place(mid_bar, position=(0, BAR_X + T / 2, BARS[1]), face="front", up="up")
    Place(low_bar, position=(0, BAR_X + T / 2, BARS[0]), face="front", up="up")
    shelf = shelf_part()
    Place(shelf, position=(0, -FOOT / 2, SHELF_Y - T / 2), face="up", up="back")

    # flat on the sheet
    RightOf(rail[1], rail[0], gap=10)
    AlignBottom(rail[1], rail[0])
    RightOf(top_bar, rail[1], gap=10)
    AlignTop(top_bar, rail[1])
    Below(mid_bar, top_bar, gap=10)
    AlignLeft(mid_bar, top_bar)
    Below(low_bar, mid_bar, gap=10)
    AlignLeft(low_bar, mid_bar)
    Below(shelf, low_bar, gap=10)
    AlignLeft(shelf, low_bar)

    assert rail[0].body.points[6].y - rail[0].body.points[0].y == 600 mm, "rails 600 tall"
    assert rail[0].body.points[2].x - rail[0].body.points[7].x == 70 mm, "70 deep at the lumbar"
    assert rail[0].body.points[2].y - rail[0].body.points[0].y == 150 mm, "lumbar 150 up"
    assert rail[0].body.points[8].x - rail[0].body.points[0].x == 180 mm, "foot 180 forward"
    assert rail[0].body.points[10].y - rail[0].body.points[0].y == 40 mm, "foot 40 high"
    assert top_bar.body.bb.width == 320 mm and top_bar.body.bb.height == 60 mm, "bars 320 x 60"
    assert rail[0].bar_slot[0].slot[0].bb.center_y - rail[0].body.points[0].y == 120 mm,
        "bottom bar 120 up"
    assert rail[0].bar_slot[2].slot[0].bb.center_y - rail[0].body.points[0].y == 540 mm,
        "top bar 540 up"
    assert rail[0].bar_slot[0].slot[0].bb.center_x - rail[0].body.points[7].x == 12 mm,
        "bars 12 behind the front edge"
    assert top_bar.straps.st[1].center.x - top_bar.straps.st[0].center.x == 120 mm, "shoulder 120"
    assert mid_bar.straps.st[1].center.x - mid_bar.straps.st[0].center.x == 200 mm, "lashing 200"
    assert low_bar.straps.st[1].center.x - low_bar.straps.st[0].center.x == 260 mm, "hip 260"
    assert shelf.body.bb.height == 180 mm and shelf.body.bb.width == 320 mm, "shelf 180 x 320"
    assert len(shelf.lashing.s) == 4, "four lashing slots"
    assert len(rail[0].cords.c) == 4, "four cord holes"
    assert distance(rail[0].cords, rail[0].bar_slot) >= 5 mm, "cord holes clear of the mortises"
    assert distance(mid_bar.mark, mid_bar.straps) >= 5 mm, "TRAIL between the lashing slots"
}
