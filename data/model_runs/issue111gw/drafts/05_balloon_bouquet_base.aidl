# Request: a party-table base for a bouquet of five balloons on standard 6 mm balloon sticks,
# cut from 3 mm ply. Two five-pointed stars 160 mm across the tips (inner notches at 40 mm
# radius, tips rounded 5 mm), one on the table and one 40 mm above it, held apart by two
# parallel uprights 50 mm wide standing 20 mm either side of the centre, each glued by two
# 10 mm tabs into mortises in both stars. The top star has a 6.5 mm hole 58 mm out on each
# tip's centre line for the sticks (they stand on the bottom star). On the top star stands
# the birthday girl's name "MIA" as cut-out bold letters 30 mm tall, joined by a 6 mm rail
# under them, held by one 24 mm tab in a slot at the star's centre.

import "std/joints.aidl"

thickness 3 mm

param outer_r = 80 mm, min = 60 mm, max = 110 mm
param gap_h = 40 mm, min = 25 mm, max = 80 mm
param name = "MIA"
t = 3 mm
up_w = 50 mm
up_y = 20 mm
stick_r = 58 mm

def star_plate() -> solid {
    s = Star(center=(0, 0), points=5, outer_radius=outer_r, inner_radius=40 mm, tip_radius=5 mm)
    front_m = tab_and_slot(part="slot", length=up_w, thickness=t, tabs=2, tab=10 mm, screw=0,
                           cx=0 mm, cy=-up_y)
    back_m = tab_and_slot(part="slot", length=up_w, thickness=t, tabs=2, tab=10 mm, screw=0,
                          cx=0 mm, cy=up_y)
}

def upright() -> solid {
    body = Rectangle(center=(0, 0), width=up_w, height=gap_h + 2 * t)
    top_tabs = tab_and_slot(part="tab", length=up_w, thickness=t, tabs=2, tab=10 mm, screw=0,
                            cx=0 mm, cy=gap_h / 2 + t)
    bottom_tabs = tab_and_slot(part="tab", length=up_w, thickness=t, tabs=2, tab=10 mm, screw=0,
                               rotation=180 deg, cx=0 mm, cy=-gap_h / 2 - t)
}

assembly balloon_base {
    bottom = star_plate()
    top = star_plate()
    # the top star also holds the sticks and the name
    hole stick {
        c = Circle(center=(0, stick_r), diameter=6.5)
    }
    sticks = CircularPattern(stick, 5, top.s.center)
    AlignCenterX(stick, top.s)
    VerticalDistance(top.s.center, stick.c.center, stick_r)
    CutInto(sticks, top)
    name_m = tab_and_slot(part="slot", length=40 mm, thickness=t, tabs=1, tab=24 mm, screw=0,
                          cx=0 mm, cy=0 mm)
    CenterInside(name_m, top.s)
    CutInto(name_m, top)

    front_up = upright()
    back_up = upright()

    solid name_plate {
        word = Text(name, position=(0, 5), size=30, font="sans:Bold")
        rail = Rectangle(bottom_left=(word.bb.left, 0), width=word.bb.width, height=6)
        # the tenon under the rail's middle (the word is centred on x = 0), into the top star
        tab = Rectangle(bottom_left=(-12, -3), width=24, height=4)
    }

    Place(bottom, position=(0, 0, 0))
    Place(top, position=(0, 0, gap_h + t))
    Place(front_up, position=(0, -up_y + t / 2, gap_h / 2 + t), face="front", up="up")
    Place(back_up, position=(0, up_y + t / 2, gap_h / 2 + t), face="front", up="up")
    Place(name_plate, position=(0, t / 2, gap_h + 2 * t), face="front", up="up")

    # on the sheet
    RightOf(top, bottom, gap=8)
    AlignTop(top, bottom)
    Below(front_up, bottom, gap=8)
    AlignLeft(front_up, bottom)
    RightOf(back_up, front_up, gap=8)
    AlignTop(back_up, front_up)
    RightOf(name_plate, back_up, gap=8)
    AlignTop(name_plate, back_up)

    assert top.s.outer_radius * 2 == 160 mm, "160 mm across the tips"
    assert len(sticks) == 5, "five sticks"
    assert stick.c.diameter == 6.5 mm, "6.5 mm stick holes"
    assert distance(stick.c.center, top.s.center) == 58 mm, "sticks 58 mm out"
    assert front_up.body.bb.height - 2 * 3 mm == 40 mm, "stars 40 mm apart"
    assert front_up.body.bb.width == 50 mm, "uprights 50 mm wide"
    assert distance(sticks, top.front_m) >= 5 mm, "stick holes clear of the mortises"
}
