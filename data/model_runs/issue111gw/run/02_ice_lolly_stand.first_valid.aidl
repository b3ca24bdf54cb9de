# Request: a freezer stand for eight ice-lolly moulds, cut from 3 mm acrylic. A deck
# 200 x 110 mm with 8 round holes of 32 mm (2 rows of 4, 42 mm apart along the rows, the
# rows 44 mm apart, the grid centred) that the mould cups hang in. The deck rests on two
# end legs 90 mm tall (deck underside 90 mm above the table), each leg as deep as the deck
# (110 mm), with a round-topped arch cut up from the bottom edge, 70 mm wide and 55 mm high,
# leaving two feet. Each leg is glued into the deck by two 25 mm tabs through mortises 5 mm
# in from the deck's ends. "ICE LOLLIES" engraved in 7 mm capitals on the deck's front strip,
# centred.

import "std/joints.aidl"

thickness 3 mm

param deck_w = 200 mm, min = 160 mm, max = 260 mm
param deck_d = 110 mm, min = 90 mm, max = 140 mm
param hole_d = 32 mm, min = 25 mm, max = 36 mm
param height = 90 mm, min = 60 mm, max = 140 mm
pitch_x = 42 mm
pitch_y = 44 mm
t = 3 mm
leg_x = deck_w / 2 - 5 mm - t / 2   # the mortises' centre line, 5 mm in from each end

def leg() -> solid {
    body = Rectangle(bottom_left=(-deck_d / 2, 0), width=deck_d, height=height + t)
    tabs = tab_and_slot(part="tab", length=deck_d, thickness=t, tabs=2, tab=25 mm, screw=0,
                        cx=0 mm, cy=height + t)
    hole arch {
        base = Rectangle(bottom_left=(-35, -2), width=70, height=22, overrun=true)
        top = Circle(center=(0, 20), radius=35)
    }
}

assembly lolly_stand {
    solid deck {
        plate = Rectangle(center=(0, 0), width=deck_w, height=deck_d)
        hole cup {
            c = Circle(center=(-1.5 * pitch_x, -pitch_y / 2), diameter=hole_d)
        }
        cups = GridPattern(cup, 2, 4, (pitch_x, pitch_y))
        left_m = tab_and_slot(part="slot", length=deck_d, thickness=t, tabs=2, tab=25 mm,
                              screw=0, rotation=90 deg, cx=-leg_x, cy=0 mm)
        right_m = tab_and_slot(part="slot", length=deck_d, thickness=t, tabs=2, tab=25 mm,
                               screw=0, rotation=90 deg, cx=leg_x, cy=0 mm)
        drawing label {
            word = Text("ICE LOLLIES", position=(0, 0), size=7, valign="middle")
        }
        Fixed(plate)
        AlignCenterX(label, plate)
        # centred in the strip between the front row of cups and the deck's front edge
        label.bb.center_y == (plate.bb.bottom + cup.c.bottom.y) / 2
    }
    left_leg = leg()
    right_leg = leg()

    Place(deck, position=(0, 0, height))
    Place(left_leg, position=(-leg_x - t / 2, 0, 0), face="right", up="up")
    Place(right_leg, position=(leg_x - t / 2, 0, 0), face="right", up="up")

    # on the sheet: the legs side by side under the deck
    Below(left_leg, deck, gap=8)
    AlignLeft(left_leg, deck)
    RightOf(right_leg, left_leg, gap=8)
    AlignTop(right_leg, left_leg)

    assert len(deck.cups) == 8, "eight cups"
    assert deck.cup.c.diameter == 32 mm, "32 mm cups"
    assert deck.cups[1].c.center.x - deck.cups[0].c.center.x == 42 mm, "42 mm along a row"
    assert deck.cups[4].c.center.y - deck.cups[0].c.center.y == 44 mm, "rows 44 mm apart"
    assert deck.plate.bb.width == 200 mm and deck.plate.bb.height == 110 mm, "deck 200 x 110"
    assert left_leg.body.bb.height - 3 mm == 90 mm, "the deck's underside 90 mm up"
    assert left_leg.arch.top.bb.top == 55 mm and left_leg.arch.top.diameter == 70 mm, "arch 70 wide, 55 high"
    assert deck.left_m.slot[0].bb.left - deck.plate.bb.left == 5 mm, "mortises 5 mm in from the ends"
    assert distance(deck.label, deck.cups) >= 2 mm, "the label clear of the cups"
}
