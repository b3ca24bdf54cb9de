# Request (home): a weekly chore chart for the kitchen wall. A 300 x 200 mm board of 6 mm birch
# ply with 8 mm rounded corners. At the top the title "CHORES" as bold filled letters, 14 mm tall,
# centred 28 mm below the top edge. Three rows, one per child ("AVA", "BEN", "CLEO", engraved
# 7 mm tall in a 60 mm name column starting 10 mm in from the left edge), and seven day columns
# (M T W T F S S engraved 6 mm tall above each column). Every cell gets a 6.5 mm hole for a
# 6 mm dowel peg: column pitch 30 mm, row pitch 35 mm, the first row 15 mm above the board's
# centre line. Two keyholes (8 mm head, 4 mm slot, 10 mm long, pointing up) 240 mm apart,
# heads 20 mm below the top edge, to hang it on two screws. Along the bottom, engraved
# 5 mm tall: "PEG IN = JOB DONE".

import "std/plates.aidl"

units mm
thickness 6 mm

param board_w = 300 mm, min = 240, max = 400
param board_h = 200 mm, min = 180, max = 260
param pitch_x = 30 mm, min = 24, max = 34
param pitch_y = 35 mm, min = 28, max = 40

names = ["AVA", "BEN", "CLEO"]
days = ["M", "T", "W", "T", "F", "S", "S"]
first_col_x = -60 mm
first_row_y = 15 mm

solid chart {
    body = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=8)

    hole peg {
        c = Circle(center=(first_col_x, first_row_y), diameter=6.5)
    }
    pegs = GridPattern(peg, len(names), len(days), (pitch_x, -pitch_y))

    hang_l = keyhole(head=8, slot_width=4, length=10, direction=90 deg, cx=-120, cy=board_h / 2 - 20)
    hang_r = keyhole(head=8, slot_width=4, length=10, direction=90 deg, cx=120, cy=board_h / 2 - 20)

    drawing title {
        t = Text("CHORES", position=(0, board_h / 2 - 28), size=14, font="sans:Bold",
                 valign="middle", fill=true)
    }

    drawing day_labels {
        for i in range(len(days)) {
            d = Text(days[i], position=(first_col_x + i * pitch_x, first_row_y + 30), size=6,
                     valign="middle")
        }
    }

    drawing name_labels {
        for j in range(len(names)) {
            n = Text(names[j], position=(-board_w / 2 + 10, first_row_y - j * pitch_y), size=7,
                     anchor="start", valign="middle")
        }
    }

    drawing footer {
        f = Text("PEG IN = JOB DONE", position=(0, -board_h / 2 + 12), size=5, valign="middle")
    }

    # the request's own numbers
    assert body.bb.width == 300 mm and body.bb.height == 200 mm, "board 300 x 200"
    assert len(pegs) == 21, "3 children x 7 days"
    assert abs(pegs[1].c.center.x - pegs[0].c.center.x - 30 mm) < 0.01, "column pitch 30"
    assert abs(pegs[0].c.center.y - pegs[7].c.center.y - 35 mm) < 0.01, "row pitch 35"
    assert abs(hang_r.head_hole.center.x - hang_l.head_hole.center.x - 240 mm) < 0.01, "keyholes 240 apart"
    assert abs(body.bb.top - hang_l.head_hole.center.y - 20 mm) < 0.01, "keyhole heads 20 below the top"
    assert pegs[20].c.center.x + 3.25 < body.bb.right - 10, "last column clear of the right edge"
    assert name_labels.bb.right < pegs[0].c.center.x - 8, "names clear of the first peg column"
    assert pegs[20].c.center.y - 3.25 > footer.bb.top + 5, "footer clear of the last row"
    assert day_labels.bb.top < title.bb.bottom - 4, "day letters under the title"
}
