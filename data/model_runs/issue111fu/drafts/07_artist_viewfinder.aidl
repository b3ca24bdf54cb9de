# Request: a painter's viewfinder card.
# - The card: 3 mm grey acrylic, 170 x 100 mm, 6 mm corners. Three windows in a row, their
#   centres 8 mm above the card's middle: 36 x 48 mm (3:4 portrait), 50 x 40 mm (5:4
#   landscape), 40 x 40 mm (1:1); 12 mm of card at each end and 10 mm between windows.
#   Under each window, 5 mm below it, its ratio engraved 5 mm tall: "3:4", "5:4", "1:1".
#   A millimetre scale along the top edge: ticks every 5 mm over 150 mm, centred, starting
#   2 mm below the edge, 4 mm long at every 10 mm and 2 mm between, numbered 0 to 15 (cm),
#   2.5 mm figures, kept 3 mm clear of the windows. A 5 mm lanyard hole, its centre 8 mm in
#   from the bottom-left corner's two edges.
# - A clear 2 mm acrylic insert glued behind the 3:4 window, 4 mm bigger than the window all
#   round, engraved with the rule-of-thirds grid of that window (two lines each way).

units mm

W = [36, 50, 40]
H = [48, 40, 40]
NAMES = ["3:4", "5:4", "1:1"]

assembly viewfinder {
    solid card {
        thickness 3 mm
        body = RoundedRectangle(center=(0, 0), width=170, height=100, corner_radius=6)
        hole windows {
            a = Rectangle(center=(-55, 8), width=W[0], height=H[0])
            b = Rectangle(center=(-2, 8), width=W[1], height=H[1])
            c = Rectangle(center=(53, 8), width=W[2], height=H[2])
        }
        hole lanyard { c = Circle(center=(-77, -42), diameter=5) }
        drawing ratios {
            ra = Text(NAMES[0], position=(-55, 8 - H[0] / 2 - 5), size=5, valign="top")
            rb = Text(NAMES[1], position=(-2, 8 - H[1] / 2 - 5), size=5, valign="top")
            rc = Text(NAMES[2], position=(53, 8 - H[2] / 2 - 5), size=5, valign="top")
        }
        drawing scale {
            for i in range(31) {
                tick = Line((-75 + i * 5, 48), (-75 + i * 5, 48 - (4 if i % 2 == 0 else 2)))
            }
            for k in range(16) {
                n = Text(str(k), position=(-75 + k * 10, 40), size=2.5, valign="top")
            }
        }
        Fixed(body)
        assert body.width == 170 mm and body.height == 100 mm, "card 170 x 100"
        assert windows.a.bb.left - body.bb.left == 12 mm, "12 mm at the left end"
        assert body.bb.right - windows.c.bb.right == 12 mm, "12 mm at the right end"
        assert windows.b.bb.left - windows.a.bb.right == 10 mm, "10 mm between"
        assert windows.c.bb.left - windows.b.bb.right == 10 mm, "10 mm between"
        assert windows.a.width / windows.a.height == 3 / 4, "3:4"
        assert windows.b.width / windows.b.height == 5 / 4, "5:4"
        assert windows.c.width == windows.c.height, "1:1"
        assert windows.a.center.y - body.center.y == 8 mm, "windows 8 mm above the middle"
        assert windows.a.bb.bottom - ratios.ra.bb.top >= 4 mm, "ratio under its window"
        assert len(scale.tick) == 31, "ticks every 5 mm over 150 mm"
        assert scale.tick[30].start.x - scale.tick[0].start.x == 150 mm, "150 mm scale"
        assert body.bb.top - scale.tick[0].start.y == 2 mm, "ticks 2 mm below the edge"
        assert distance(scale, windows) >= 3 mm, "scale clear of the windows"
        assert distance(scale, body.bb.top_left) >= 0 mm, "scale on the card"
        assert lanyard.c.center.x - body.bb.left == 8 mm and lanyard.c.center.y - body.bb.bottom == 8 mm, "lanyard 8 mm in"
        assert distance(lanyard, ratios) >= 3 mm, "lanyard clear of the labels"
    }

    solid insert {
        thickness 2 mm
        pane = Rectangle(center=(0, 0), width=W[0] + 8, height=H[0] + 8)
        drawing thirds {
            v1 = Line((-W[0] / 6, -H[0] / 2), (-W[0] / 6, H[0] / 2))
            v2 = Line((W[0] / 6, -H[0] / 2), (W[0] / 6, H[0] / 2))
            h1 = Line((-W[0] / 2, -H[0] / 6), (W[0] / 2, -H[0] / 6))
            h2 = Line((-W[0] / 2, H[0] / 6), (W[0] / 2, H[0] / 6))
        }
        Fixed(pane)
        assert pane.width - W[0] == 8 mm, "4 mm bigger all round"
        assert thirds.v2.start.x - thirds.v1.start.x == W[0] / 3, "thirds"
    }

    RightOf(insert, card, gap=10)
    AlignTop(insert, card)

    # the insert behind the 3:4 window, against the card's back
    Place(card, position=(0, 0, 0))
    Place(insert, on=card, position=(-55, 8, -2))
}
