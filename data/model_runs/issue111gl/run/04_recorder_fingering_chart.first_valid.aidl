# Request: a wall chart for my recorder class, 3 mm birch ply, 300 x 180 mm with 8 mm
# corners, hung on two screws by keyholes (8 mm head, 4 mm slot 10 mm long, pointing up)
# 25 mm in from the sides and 28 mm down from the top. Engraved: the title "SOPRANO
# RECORDER - BAROQUE FINGERING" across the top; a stave (5 lines 5 mm apart, the bottom
# line 35 mm above the centre) with the C major scale from middle C (on a ledger line) to
# the C above, as filled note heads with stems, one note over each of 8 columns 32 mm apart;
# under each note its fingering: the thumb hole 10 mm left of the column and the 7 finger
# holes down the column (11 mm apart, 15 mm between the hands), 6 mm circles, filled where
# the hole is covered, an outline where it is open; the note's name under its column, and
# "LEFT" / "RIGHT" beside the two hands of the first column.

import "std/plates.aidl"

units mm
thickness 3 mm

board_w = 300 mm
board_h = 180 mm
col_pitch = 32 mm
cols = 8
col_x = [-(cols - 1) / 2 * col_pitch + i * col_pitch for i in range(cols)]
hole_d = 6 mm
# thumb, then finger holes 1-7: left hand 1-3, right hand 4-7
hole_y = [19 mm, 14 mm, 3 mm, -8 mm, -23 mm, -34 mm, -45 mm, -56 mm]
hole_dx = [-10 mm, 0 mm, 0 mm, 0 mm, 0 mm, 0 mm, 0 mm, 0 mm]
# baroque fingering, 1 = covered: thumb, 1, 2, 3, 4, 5, 6, 7
fingers = [[1, 1, 1, 1, 1, 1, 1, 1],
           [1, 1, 1, 1, 1, 1, 1, 0],
           [1, 1, 1, 1, 1, 1, 0, 0],
           [1, 1, 1, 1, 1, 0, 1, 1],
           [1, 1, 1, 1, 0, 0, 0, 0],
           [1, 1, 1, 0, 0, 0, 0, 0],
           [1, 1, 0, 0, 0, 0, 0, 0],
           [1, 0, 1, 0, 0, 0, 0, 0]]
names = ["C", "D", "E", "F", "G", "A", "B", "C'"]
# staff steps from the bottom line (E): C below the stave on a ledger line ... C in the third space
steps = [-2, -1, 0, 1, 2, 3, 4, 5]
staff_bottom = 35 mm
staff_gap = 5 mm
covered = [(col_x[i] + hole_dx[h], hole_y[h]) for i in range(cols) for h in range(8) if fingers[i][h] == 1]
open_holes = [(col_x[i] + hole_dx[h], hole_y[h]) for i in range(cols) for h in range(8) if fingers[i][h] == 0]
head_y = [staff_bottom + s * staff_gap / 2 for s in steps]

solid chart {
    board = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=8)
    Fixed(board)

    hang_l = keyhole(head=8, slot_width=4, length=10, direction=90 deg)
    hang_r = keyhole(head=8, slot_width=4, length=10, direction=90 deg)
    hang_l.head_hole.center == (-board_w / 2 + 25 mm, board_h / 2 - 28 mm)
    hang_r.head_hole.center == (board_w / 2 - 25 mm, board_h / 2 - 28 mm)

    drawing title {
        words = Text("SOPRANO RECORDER - BAROQUE FINGERING", position=(0, 76), size=6,
                     valign="middle")
    }

    drawing stave {
        for k in range(5) {
            staff_line = Line((-140, staff_bottom + k * staff_gap), (140, staff_bottom + k * staff_gap))
        }
        ledger = Line((col_x[0] - 6, head_y[0]), (col_x[0] + 6, head_y[0]))
        for i in range(cols) {
            head = Ellipse(center=(col_x[i], head_y[i]), rx=3.2, ry=2.3, rotation=20 deg, fill=true)
            # stems up on the right below the middle line, down on the left from it
            if steps[i] < 4 {
                stem = Line((col_x[i] + 3, head_y[i] + 1), (col_x[i] + 3, head_y[i] + 17.5))
            } else {
                stem = Line((col_x[i] - 3, head_y[i] - 1), (col_x[i] - 3, head_y[i] - 17.5))
            }
        }
    }

    drawing holes_shown {
        for p in covered {
            shut = Circle(center=p, diameter=hole_d, fill=true)
        }
        for p in open_holes {
            open_ring = Circle(center=p, diameter=hole_d)
        }
    }

    drawing labels {
        for i in range(cols) {
            name = Text(names[i], position=(col_x[i], -72), size=7, valign="middle")
        }
        left_hand = Text("LEFT", position=(col_x[0] - 24, 3), size=4, valign="middle", rotation=90 deg)
        right_hand = Text("RIGHT", position=(col_x[0] - 24, -39.5), size=4, valign="middle", rotation=90 deg)
    }

    assert board.width == 300 mm and board.height == 180 mm, "300 x 180 board"
    assert hang_l.head_hole.center.x - board.bb.left == 25 mm, "keyholes 25 mm from the sides"
    assert board.bb.top - hang_l.head_hole.center.y == 28 mm, "keyholes 28 mm down"
    assert distance(hang_l, title) >= 3 mm and distance(hang_r, title) >= 3 mm, "keyholes clear of the title"
    assert len(col_x) == 8 and col_x[1] - col_x[0] == 32 mm, "8 columns 32 mm apart"
    assert len(covered) + len(open_holes) == 64, "8 holes in each of 8 columns"
    assert hole_y[1] - hole_y[2] == 11 mm and hole_y[3] - hole_y[4] == 15 mm, "11 mm apart, 15 between the hands"
    assert col_x[0] + hole_dx[0] == col_x[0] - 10 mm, "thumb 10 mm left"
    assert stave.bb.bottom > holes_shown.bb.top, "the notes stay above the fingerings"
    assert labels.bb.bottom > board.bb.bottom + 5 mm, "names on the board"
    assert labels.bb.left > board.bb.left + 5 mm, "LEFT/RIGHT on the board"
    assert sum(fingers[0]) == 8 and fingers[3][5] == 0, "C all covered; baroque F opens hole 5"
}
