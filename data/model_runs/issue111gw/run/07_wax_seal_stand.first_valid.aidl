# Request: a desk stand for wax-sealing tools, cut from 3 mm ply. Two decks 160 x 80 mm
# between two side panels: a bottom deck 8 mm above the table and a top deck 60 mm above it,
# each glued into both sides by two 20 mm tabs. The top deck holds three seal stamps in 16 mm
# holes (a row, 25 mm apart, the first 55 mm left of centre, 8 mm behind the deck's middle)
# whose handles stand on the bottom deck; four square 12 mm pockets for sealing-wax sticks (a
# 2 x 2 grid at 20 mm pitch, its first at (25, -2) mm from the deck's centre); and a 14 mm
# round-ended notch 20 mm deep in the front edge, 60 mm right of centre, for the melting
# spoon's handle. "WAX SEALS" engraved in 6 mm capitals on the front strip, under the stamps.
# The sides are 80 mm deep, 95 mm tall, their top corners rounded 20 mm, each with a 40 x 12
# mm carrying slot centred 80 mm up.

import "std/joints.aidl"

thickness 3 mm

param deck_w = 160 mm, min = 120 mm, max = 220 mm
param deck_d = 80 mm, min = 70 mm, max = 120 mm
t = 3 mm
low_z = 8 mm
top_z = 60 mm
side_h = 95 mm

def deck() -> solid {
    plate = Rectangle(center=(0, 0), width=deck_w + 2 * t, height=deck_d)
    left_tabs = tab_and_slot(part="tab", length=deck_d, thickness=t, tabs=2, tab=20 mm, screw=0,
                             rotation=90 deg, cx=-deck_w / 2 - t, cy=0 mm)
    right_tabs = tab_and_slot(part="tab", length=deck_d, thickness=t, tabs=2, tab=20 mm, screw=0,
                              rotation=-90 deg, cx=deck_w / 2 + t, cy=0 mm)
}

def side() -> solid {
    body = RoundedRectangle(bottom_left=(-deck_d / 2, 0), width=deck_d, height=side_h,
                            corner_radii=[20, 20, 0, 0])
    low_m = tab_and_slot(part="slot", length=deck_d, thickness=t, tabs=2, tab=20 mm, screw=0,
                         cx=0 mm, cy=low_z + t / 2)
    top_m = tab_and_slot(part="slot", length=deck_d, thickness=t, tabs=2, tab=20 mm, screw=0,
                         cx=0 mm, cy=top_z + t / 2)
    hole grip {
        s = Slot(center=(0, 80), length=40, width=12)
    }
}

assembly wax_stand {
    low = deck()
    top = deck()
    hole stamp {
        c = Circle(center=(-55, 8), diameter=16)
    }
    stamps = LinearPattern(stamp, 3, (25, 0))
    hole wax {
        sq = Rectangle(center=(25, -2), width=12, height=12)
    }
    sticks = GridPattern(wax, 2, 2, (20, 20))
    hole spoon {
        s = Slot(start=(60, -deck_d / 2 - 5), end=(60, -deck_d / 2 + 20 - 7), width=14, overrun=true)
    }
    drawing label {
        w = Text("WAX SEALS", position=(0, 0), size=6, valign="middle")
    }
    # the top deck's features, placed from its centre
    At(stamp.c.center, top.plate.center, dx=-55, dy=8)
    At(wax.sq.center, top.plate.center, dx=25, dy=-2)
    At(spoon.s.end, top.plate.center, dx=60, dy=-deck_d / 2 + 20 - 7)
    label.bb.center_x == stamps[1].c.center.x
    label.bb.center_y == (top.plate.bb.bottom + stamp.c.bottom.y) / 2
    CutInto(stamps, top)
    CutInto(sticks, top)
    CutInto(spoon, top)
    CutInto(label, top)

    left = side()
    right = side()

    Place(low, position=(0, 0, low_z))
    Place(top, position=(0, 0, top_z))
    Place(left, position=(-deck_w / 2, 0, 0), face="left", up="up")
    Place(right, position=(deck_w / 2, 0, 0), face="right", up="up")

    # on the sheet
    RightOf(top, low, gap=8)
    AlignTop(top, low)
    Below(left, low, gap=8)
    AlignLeft(left, low)
    RightOf(right, left, gap=8)
    AlignTop(right, left)

    assert top.plate.bb.width - 2 * 3 mm == 160 mm and top.plate.bb.height == 80 mm, "decks 160 x 80"
    assert len(stamps) == 3 and stamp.c.diameter == 16 mm, "three 16 mm stamp holes"
    assert stamps[1].c.center.x - stamps[0].c.center.x == 25 mm, "stamps 25 mm apart"
    assert len(sticks) == 4 and wax.sq.width == 12 mm, "four 12 mm wax pockets"
    assert top.plate.bb.bottom + 20 mm - (spoon.s.end.y + 7 mm) == 0 mm, "spoon notch 20 mm deep"
    assert spoon.s.width == 14 mm, "spoon notch 14 wide"
    assert left.top_m.slot[0].bb.center_y - left.low_m.slot[0].bb.center_y == 60 mm - 8 mm, "decks at 8 and 60 mm"
    assert left.body.bb.height == 95 mm and left.body.bb.width == 80 mm, "sides 80 x 95"
    assert distance(label, stamps) >= 2 mm, "label clear of the stamps"
    assert distance(stamps, sticks) >= 3 mm and distance(sticks, spoon) >= 3 mm, "features apart"
}
