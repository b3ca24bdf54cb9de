# Sport / camping: an orienteering romer card, 2 mm acrylic. Card 80 x 55 mm, corner
# radius 4 mm. Two romer scales engraved as ticks from the card's edges, each counting
# 100 m steps up to 1 km from its corner (ticks 1 to 10; the corner itself is 0):
# - 1:25 000 at the bottom-right corner: 4 mm per 100 m (1 km = 40 mm), along the bottom
#   edge (leftward) and up the right edge; ticks 3 mm long, the 500 m tick 5 mm, the 1 km
#   tick 6 mm; "1:25000" engraved 3 mm tall.
# - 1:50 000 at the top-left corner: 2 mm per 100 m (1 km = 20 mm), along the top edge
#   (rightward) and down the left edge; ticks 1.5 mm, the 500 m tick 2.5 mm, the 1 km tick
#   3 mm; "1:50000" engraved 3 mm tall.
# "ROMER" engraved 6 mm tall in the middle; a 4 mm lanyard hole 6 mm from the top and right
# edges.

thickness 2 mm

solid romer {
    # the two scale corners stay sharp: each romer reads from its corner (fix after the first
    # check: W0505, the first 1:50000 ticks ran off the R4 corner)
    card = RoundedRectangle(bottom_left=(0, 0), width=80, height=55, corner_radii=[0, 4, 0, 4])

    drawing scale25 {
        for i in range(1, 11) {
            b = Line((80 - 4 * i, 0), (80 - 4 * i, 6 if i == 10 else (5 if i == 5 else 3)))
            r = Line((80, 4 * i), (80 - (6 if i == 10 else (5 if i == 5 else 3)), 4 * i))
        }
        label = Text("1:25000", (56, 9), size=3)
    }

    drawing scale50 {
        for i in range(1, 11) {
            t = Line((2 * i, 55), (2 * i, 55 - (3 if i == 10 else (2.5 if i == 5 else 1.5))))
            l = Line((0, 55 - 2 * i), ((3 if i == 10 else (2.5 if i == 5 else 1.5)), 55 - 2 * i))
        }
        label = Text("1:50000", (16, 44), size=3)
    }

    drawing title {
        word = Text("ROMER", (40, 27.5), size=6, valign="middle")
    }

    hole lanyard {
        c = Circle(center=(74, 49), diameter=4)
    }

    assert card.width == 80 mm and card.height == 55 mm, "card 80 x 55"
    assert len(scale25.b) == 10 and len(scale25.r) == 10, "10 ticks each way (1:25000)"
    assert len(scale50.t) == 10 and len(scale50.l) == 10, "10 ticks each way (1:50000)"
    assert card.bb.right - scale25.b[9].start.x == 40 mm, "1 km = 40 mm at 1:25000"
    assert scale25.r[9].start.y - card.bb.bottom == 40 mm, "1 km = 40 mm up the right edge"
    assert scale50.t[9].start.x - card.bb.left == 20 mm, "1 km = 20 mm at 1:50000"
    assert card.bb.top - scale50.l[9].start.y == 20 mm, "1 km = 20 mm down the left edge"
    assert scale25.b[0].length == 3 mm and scale25.b[4].length == 5 mm and scale25.b[9].length == 6 mm, "1:25000 ticks"
    assert scale50.t[0].length == 1.5 mm and scale50.t[4].length == 2.5 mm and scale50.t[9].length == 3 mm, "1:50000 ticks"
    assert title.word.size == 6 mm and scale25.label.size == 3 mm, "text sizes"
    assert lanyard.c.diameter == 4 mm, "4 mm lanyard hole"
    assert card.bb.top - lanyard.c.center.y == 6 mm and card.bb.right - lanyard.c.center.x == 6 mm, "6 mm from the corner edges"
    assert scale25.label.bb.left > scale25.b[9].start.x, "label inside the 1:25000 scale's corner"
}
