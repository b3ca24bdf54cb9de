# Holidays: an advent calendar peg board, 4 mm plywood, 320 x 240 mm with R8 corners. 24 peg
# holes of 6 mm (for dowels that hold the little bags) in 4 rows x 6 columns, 48 mm apart
# across and 50 mm apart down, the grid centred across, its top row 60 mm below the top edge.
# Under each hole its day 1-24 (left to right, top row first) engraved 7 mm high, centred
# under the hole, the number's top 6 mm below the hole's centre. "ADVENT" engraved 16 mm high,
# centred across, its middle 30 mm below the top edge, between two five-point stars cut
# through (outer radius 10 mm, inner 4 mm) centred 90 mm either side of the middle on the
# title's line. Two keyholes (8 mm head, 4 mm slot 10 mm long, upwards) 30 mm in from each
# side, their heads 25 mm below the top edge.
units mm
thickness 4 mm
import "std/plates.aidl"

solid advent {
    board = RoundedRectangle(center=(0, 0), width=320, height=240, corner_radius=8)

    hole pegs {
        for i in range(24) {
            c = Circle(center=(-120 + (i % 6) * 48, 60 - (i // 6) * 50), diameter=6)
        }
    }
    drawing days {
        for i in range(24) {
            n = Text(str(i + 1), (-120 + (i % 6) * 48, 54 - (i // 6) * 50), size=7, valign="top")
        }
    }
    drawing title {
        word = Text("ADVENT", (0, 90), size=16, valign="middle")
    }
    hole stars {
        s_l = Star(center=(-90, 90), points=5, outer_radius=10, inner_radius=4)
        s_r = Star(center=(90, 90), points=5, outer_radius=10, inner_radius=4)
    }
    hang_l = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=-130, cy=95)
    hang_r = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=130, cy=95)

    assert board.bb.width == 320 mm and board.bb.height == 240 mm, "board 320 x 240"
    assert len(pegs.c) == 24, "24 peg holes"
    assert pegs.c[0].diameter == 6 mm, "6 mm pegs"
    assert pegs.c[1].center.x - pegs.c[0].center.x == 48 mm, "48 apart across"
    assert pegs.c[0].center.y - pegs.c[6].center.y == 50 mm, "50 apart down"
    assert pegs.c[23].center.y - pegs.c[0].center.y == -3 * 50 mm, "4 rows"
    assert (pegs.c[0].center.x + pegs.c[5].center.x) / 2 == board.center.x, "grid centred across"
    assert board.bb.top - pegs.c[0].center.y == 60 mm, "top row 60 below the top edge"
    assert len(days.n) == 24, "24 days"
    assert days.n[0].size == 7 mm, "days 7 mm"
    assert days.n[13].position.x == pegs.c[13].center.x, "day centred under its hole"
    assert pegs.c[13].center.y - days.n[13].position.y == 6 mm, "day's top 6 below the hole's centre"
    assert title.word.size == 16 mm, "ADVENT 16 mm"
    assert board.bb.top - title.word.position.y == 30 mm, "title's middle 30 below the top edge"
    assert stars.s_r.outer_radius == 10 mm and stars.s_r.inner_radius == 4 mm, "stars 10 / 4"
    assert stars.s_r.center.x - board.center.x == 90 mm and stars.s_l.center.x - board.center.x == -90 mm, "stars 90 either side"
    assert stars.s_l.center.y == title.word.position.y, "stars on the title's line"
    assert hang_l.head_hole.diameter == 8 mm and hang_l.slot.width == 4 mm, "keyhole 8 / 4"
    assert hang_l.head_hole.center.x - board.bb.left == 30 mm and board.bb.right - hang_r.head_hole.center.x == 30 mm, "30 in from each side"
    assert board.bb.top - hang_l.head_hole.center.y == 25 mm, "heads 25 below the top edge"
}
