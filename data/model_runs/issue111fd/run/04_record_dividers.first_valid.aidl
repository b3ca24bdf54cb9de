# Request (music): a set of four divider cards for an LP record shelf, in 3 mm white acrylic.
# Each card is 310 wide x 300 high with 8 mm corners, with a 70 x 30 mm index tab on top (its top
# corners rounded 6 mm, the corners where it meets the card rounded 3 mm). The tabs are
# staggered so all four can be read from the front: the first 10 mm in from the left edge, the
# last 10 mm in from the right, the other two evenly between. The ranges A-F, G-L, M-R, S-Z are
# engraved on the tab (filled bold letters 14 mm high) and on the card as the label of an
# engraved record: an outer rim 145 mm radius, grooves every 10 mm from 60 to 130 mm radius, a
# 50 mm label circle with the range in 20 mm letters, and a 7.2 mm spindle hole cut through.

thickness 3 mm

CARD_W = 310 mm
CARD_H = 300 mm
TAB_W = 70 mm
TAB_H = 30 mm
EDGE_IN = 10 mm
RANGES = ["A–F", "G–L", "M–R", "S–Z"]

# the k-th tab's centre, 10 mm in from the edges at the ends, evenly between
def tab_x(k) = -CARD_W / 2 + EDGE_IN + TAB_W / 2 + k * (CARD_W - 2 * EDGE_IN - TAB_W) / 3

def card(k=0) -> solid {
    body = RoundedRectangle(center=(0, 0), width=CARD_W, height=CARD_H, corner_radius=8)
    # the tab overlaps the card by 2 mm so the two merge
    tab = RoundedRectangle(center=(tab_x(k), CARD_H / 2 + TAB_H / 2 - 1), width=TAB_W,
                           height=TAB_H + 2, corner_radii=[6, 6, 0, 0])
    Fillet([tab, body], 3)
    hole spindle {
        c = Circle(center=(0, 0), diameter=7.2)
    }
    drawing record {
        rim = Circle(center=(0, 0), radius=145)
        for r in range(60, 131, 10) {
            groove = Circle(center=(0, 0), radius=r)
        }
        label = Circle(center=(0, 0), radius=50)
        name = Text(RANGES[k], position=(0, 20), size=20, font="sans:Bold", valign="middle",
                    fill=true)
        index = Text(RANGES[k], position=(tab_x(k), CARD_H / 2 + TAB_H / 2), size=14,
                     font="sans:Bold", valign="middle", fill=true)
    }
}

assembly dividers {
    for k in range(4) {
        c = card(k=k)
        # standing in a row on the shelf, 40 mm apart, engraving to the front
        Place(c, position=(0, 40 mm * k + 3 mm, CARD_H / 2), face="front", up="up")
    }
    # flat on the sheet: two rows of two
    RightOf(c[1], c[0], gap=10)
    AlignTop(c[1], c[0])
    Below(c[2], c[0], gap=10)
    AlignLeft(c[2], c[0])
    RightOf(c[3], c[2], gap=10)
    AlignTop(c[3], c[2])

    assert len(c) == 4, "four cards"
    assert c[0].body.bb.width == 310 mm and c[0].body.bb.height == 300 mm, "card 310 x 300"
    assert c[0].tab.bb.width == 70 mm, "tab 70 wide"
    assert c[0].tab.bb.top - c[0].body.bb.top == 30 mm, "tab stands 30 above the card"
    assert c[0].tab.bb.left - c[0].body.bb.left == 10 mm, "first tab 10 in from the left"
    assert c[3].body.bb.right - c[3].tab.bb.right == 10 mm, "last tab 10 in from the right"
    assert (c[2].tab.bb.center_x - c[2].body.bb.center_x) - (c[1].tab.bb.center_x - c[1].body.bb.center_x) ==
        (c[1].tab.bb.center_x - c[1].body.bb.center_x) - (c[0].tab.bb.center_x - c[0].body.bb.center_x),
        "tabs evenly staggered"
    assert c[0].spindle.c.diameter == 7.2 mm, "spindle hole"
    assert len(c[0].record.groove) == 8, "grooves 60 ... 130"
    assert distance(c[0].record.name, c[0].spindle) >= 3 mm, "range clear of the spindle hole"
}
