# Request (crafts): a wraps-per-inch (WPI) gauge for a hand spinner, in 3 mm ply. A card
# 120 x 86 mm with 4 mm corners. Along the top edge a window exactly 1 inch (25.4 mm) long
# and 8 mm tall leaves a 5 mm bar to wrap yarn round; along the bottom edge a 2-inch
# (50.8 mm) window leaves the same 5 mm bar. Both windows start 10 mm from the left end;
# "1 INCH" and "2 INCH" engraved 4 mm tall 4 mm right of them. Between them a table of yarn
# weights, 3.5 mm strokes, 7 mm apart: LACE 30-40, FINGERING 14-30, SPORT 12-18, DK 11-15,
# WORSTED 9-12, BULKY 7-8, SUPER BULKY 5-6 (names from the left, 10 mm in; WPI ranges
# right-aligned 10 mm from the right end). A 5 mm hole 8 mm in from the top right corner for
# a ring.

thickness 3 mm

inch = 25.4 mm
yarns = ["LACE", "FINGERING", "SPORT", "DK", "WORSTED", "BULKY", "SUPER BULKY"]
wpis = ["30-40", "14-30", "12-18", "11-15", "9-12", "7-8", "5-6"]

solid wpi_card {
    card = RoundedRectangle(center=(0, 0), width=120, height=86, corner_radius=4)
    Fixed(card)
    hole one_inch {
        w = Rectangle(bottom_left=(-50, 43 - 5 - 8), width=inch, height=8)
    }
    hole two_inch {
        w = Rectangle(bottom_left=(-50, -43 + 5), width=2 * inch, height=8)
    }
    hole ring {
        c = Circle(center=(60 - 8, 43 - 8), diameter=5)
    }
    drawing labels {
        one = Text("1 INCH", (-50 + inch + 4, 43 - 5 - 4), size=4, anchor="start", valign="middle")
        two = Text("2 INCH", (-50 + 2 * inch + 4, -43 + 5 + 4), size=4, anchor="start",
                   valign="middle")
    }
    drawing table {
        for i in range(7) {
            name = Text(yarns[i], (-50, 21 - i * 7), size=3.5, anchor="start", valign="middle")
            wpi = Text(wpis[i], (50, 21 - i * 7), size=3.5, anchor="end", valign="middle")
        }
    }

    assert one_inch.w.bb.width == 25.4 mm, "exactly one inch"
    assert two_inch.w.bb.width == 50.8 mm, "exactly two inches"
    assert card.bb.top - one_inch.w.bb.top == 5 mm, "5 mm bar at the top"
    assert two_inch.w.bb.bottom - card.bb.bottom == 5 mm, "5 mm bar at the bottom"
    assert one_inch.w.bb.left - card.bb.left == 10 mm and two_inch.w.bb.left - card.bb.left == 10 mm,
        "windows start 10 mm from the left end"
    assert len(table.name) == 7 and table.name[6].text == "SUPER BULKY", "seven yarn weights"
    assert distance(table, one_inch) >= 2 mm and distance(table, two_inch) >= 2 mm,
        "the table clears the windows"
    assert distance(labels, ring) >= 2 mm, "the 1 INCH label clears the ring hole"
    assert distance(table.name[6], table.wpi[6]) >= 5 mm, "the longest name and its range apart"
    assert card.bb.right - ring.c.center.x == 8 mm and card.bb.top - ring.c.center.y == 8 mm,
        "ring hole 8 mm in from the corner"
}
