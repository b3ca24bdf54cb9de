# The program of the 21:24:56Z check (first valid + Fixed(square)), rebuilt afterwards for the
# record with the same code (its explanatory comment aside): chk.sh keeps only attempts before
# the first valid program. Checked: W0508 + W0513, hole `middle` dragged to (-75, -75).
# Parties: a garden-party ring-toss game, 6 mm ply, as separate parts to cut.
# Base board 250 x 250 mm with R10 corners: five 12 mm holes for dowel pegs, one in the centre
# and four on the corners of a 150 mm square around it. Each peg's score engraved below it,
# its top 14 mm below the hole's centre, size 10 strokes: "10" at the corners, "25" in the middle.
# Three throwing rings 120 mm outside, 90 mm inside.
thickness 6 mm

import "std/shapes.aidl"

param board = 250 mm, min = 200, max = 400
param spread = 150 mm, min = 100, max = 300
param peg_d = 12 mm, min = 8, max = 20

assembly ring_toss {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=board, height=board, corner_radius=10)
        square = Rectangle(center=(0, 0), width=spread, height=spread, construction=true)
        hole peg {
            c = Circle(center=(0, 0), diameter=peg_d)
        }
        Fixed(square)
        pegs = CornerPattern(peg, square)
        hole middle {
            c = Circle(center=(0, 0), diameter=peg_d)
        }
        drawing scores {
            for i in range(4) {
                t = Text("10", (0, 0), size=10, valign="top")
            }
            mid = Text("25", (0, -14), size=10, valign="top")
        }
        for i in range(4) {
            At(scores.t[i].position, pegs[i].c.center, dy=-14)
        }
        At(scores.mid.position, middle.c.center, dy=-14)

        assert plate.width == 250 mm and plate.height == 250 mm, "250 x 250 base"
        assert len(pegs) == 4, "four corner pegs"
        assert pegs[3].c.center.x - pegs[0].c.center.x == 150 mm or pegs[1].c.center.x - pegs[0].c.center.x == 150 mm, "150 mm square"
        assert peg.c.diameter == 12 mm, "12 mm dowels"
    }
    r1 = washer(outer=120 mm, inner=90 mm, cx=200 mm, cy=65 mm)
    r2 = washer(outer=120 mm, inner=90 mm, cx=200 mm, cy=-65 mm)
    r3 = washer(outer=120 mm, inner=90 mm, cx=330 mm, cy=65 mm)

    assert r1.ring.diameter == 120 mm and r1.bore.b.diameter == 90 mm, "rings 120 / 90"
}
