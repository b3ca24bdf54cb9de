# Request: a forearm dive slate in 3 mm white acrylic (sanded to take pencil).
# - 160 x 110 mm, R10 corners.
# - Two strap slots 30 x 5 mm, upright, their centres 10 mm in from the left and right
#   edges, on the middle line, for a bungee round the forearm.
# - A 6 mm lanyard hole at the top left, 10 mm in from both edges; two 4 mm holes for the
#   pencil's bungee at the right, 10 mm in from the right edge, 15 and 27 mm down from the
#   top.
# - Engraved: "DIVE LOG" 8 mm tall, its middle 17 mm below the top edge, centred 10 mm left
#   of the slate's centre; a diver-down flag 24 x 18 (outline engraved, the red fields
#   fill-engraved either side of a 5 mm diagonal stripe from top left to bottom right),
#   centred 40 mm right of the centre and 15 mm below the top edge.
# - A log table engraved below: 4 columns 30 mm wide (No., DEPTH m, TIME min, BAR), 6 rows
#   12 mm tall (a header and dives 1-5), its top line 30 mm below the top edge, centred.

thickness 3 mm

W = 160 mm
H = 110 mm
COLS = 4
ROWS = 6
CW = 30 mm
RH = 12 mm
HEAD = ["No.", "DEPTH m", "TIME min", "BAR"]

# the flag: 24 x 18 centred at (40, 40); stripe 5 wide along the diagonal from its top left
# (28, 49) to its bottom right (52, 31); the stripe's edges are the diagonal moved
# 2.5 mm along its normal (0.6, 0.8): (1.5, 2) mm.
FLAG_UR = [(28 + 1.5 + 24 * 2 / 18, 49), (52, 49), (52, 49 + 2 - 18 * (52 - 29.5) / 24)]
FLAG_LL = [(28, 49 - 2 - 18 * 1.5 / 24), (28, 31), (26.5 + 24 * 16 / 18, 31)]

solid slate {
    body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=10)
    hole straps {
        left = Slot(center=(-W / 2 + 10 mm, 0), length=30, width=5, rotation=90)
        right = Slot(center=(W / 2 - 10 mm, 0), length=30, width=5, rotation=90)
    }
    hole lanyard { c = Circle(center=(-W / 2 + 10 mm, H / 2 - 10 mm), diameter=6) }
    hole pencil {
        a = Circle(center=(W / 2 - 10 mm, H / 2 - 15 mm), diameter=4)
        b = Circle(center=(W / 2 - 10 mm, H / 2 - 27 mm), diameter=4)
    }
    drawing title {
        t = Text("DIVE LOG", position=(-10, H / 2 - 17 mm), size=8, valign="middle")
    }
    drawing flag {
        edge = Rectangle(center=(40, 40), width=24, height=18)
        ur = Polygon(FLAG_UR, fill=true)
        ll = Polygon(FLAG_LL, fill=true)
    }
    drawing table {
        for r in range(ROWS + 1) {
            h = Line((-COLS * CW / 2, H / 2 - 30 mm - r * RH),
                     (COLS * CW / 2, H / 2 - 30 mm - r * RH))
        }
        for c in range(COLS + 1) {
            v = Line((-COLS * CW / 2 + c * CW, H / 2 - 30 mm),
                     (-COLS * CW / 2 + c * CW, H / 2 - 30 mm - ROWS * RH))
        }
        for c in range(COLS) {
            head = Text(HEAD[c], position=(-COLS * CW / 2 + (c + 0.5) * CW, H / 2 - 30 mm - RH / 2),
                        size=3.5, valign="middle")
        }
        for r in range(ROWS - 1) {
            num = Text(str(r + 1), position=(-COLS * CW / 2 + CW / 2, H / 2 - 30 mm - (r + 1.5) * RH),
                       size=4, valign="middle")
        }
    }

    assert body.bb.width == 160 mm and body.bb.height == 110 mm, "160 x 110"
    assert straps.left.length == 30 mm and straps.left.width == 5 mm, "strap slots 30 x 5"
    assert straps.left.center.x - body.bb.left == 10 mm, "straps 10 in"
    assert body.bb.right - straps.right.center.x == 10 mm, "straps 10 in (right)"
    assert lanyard.c.diameter == 6 mm and body.bb.top - lanyard.c.center.y == 10 mm, "lanyard"
    assert pencil.a.center.y - pencil.b.center.y == 12 mm, "pencil holes 15 and 27 down"
    assert len(table.h) == 7 and len(table.v) == 5, "6 rows, 4 columns"
    assert table.h[0].start.y - table.h[1].start.y == 12 mm, "rows 12"
    assert table.v[1].start.x - table.v[0].start.x == 30 mm, "columns 30"
    assert body.bb.top - table.h[0].start.y == 30 mm, "table 30 below the top"
    assert table.bb.bottom - body.bb.bottom >= 5 mm, "table on the slate"
    assert distance(table, straps) >= 3 mm, "table clear of the straps"
    assert distance(title, flag) >= 3 mm, "title clear of the flag"
    assert distance(flag, pencil) >= 2 mm, "flag clear of the pencil holes"
    assert flag.edge.bb.width == 24 mm and flag.edge.bb.height == 18 mm, "flag 24 x 18"
}
