# Request (science / maths class): a coordinate geoboard for rubber bands, 6 mm ply.
# - Top board 200 x 200 mm, R6 corners, with an 11 x 11 grid of 5.9 mm holes (press fit
#   for 6 mm dowel pegs) on a 15 mm pitch; the grid's bottom-left hole 30 mm from the
#   left and bottom edges.
# - The numbers 0 to 10 engraved (4 mm strokes) under each column and left of each row,
#   8 mm from the hole centres; "GEOBOARD" engraved 6 mm high, centred, 10 mm from the
#   top edge.
# - A plain base board of the same outline glued under it, so the pegs stop on it.

thickness 6 mm

param pitch = 15 mm, min = 12 mm, max = 16 mm
n = 11
board = 200 mm
first = -board / 2 + 30 mm      # the bottom-left hole's x and y

assembly geoboard {
    solid top {
        body = RoundedRectangle(center=(0, 0), width=board, height=board, corner_radius=6)
        hole peg {
            c = Circle(center=(first, first), diameter=5.9)
        }
        pegs = GridPattern(peg, n, n, pitch)
        drawing numbers {
            for i in range(n) {
                col = Text(str(i), position=(first + i * pitch, first - 8 mm), size=4,
                           valign="middle")
                # FIX after the first valid program: centred 8 mm left of the hole, "10"
                # ended 1.5 mm from it and read as "10O"; now right-aligned 6 mm from the
                # centre (3 mm clear of the hole's edge)
                row = Text(str(i), position=(first - 6 mm, first + i * pitch), size=4,
                           anchor="end", valign="middle")
            }
            title = Text("GEOBOARD", position=(0, board / 2 - 10 mm), size=6, valign="middle")
        }
        Fixed(body)
        Fixed(peg)
        Fixed(numbers)
    }

    solid base {
        body = RoundedRectangle(center=(0, 0), width=board, height=board, corner_radius=6)
    }
    RightOf(base, top, gap=8)
    AlignTop(base, top)

    Place(base, position=(0, 0, 0), face="up")
    Place(top, position=(0, 0, 6 mm), face="up")

    # the request's numbers
    assert len(top.pegs) == 121, "11 x 11 holes"
    assert top.pegs[1].c.center.x - top.pegs[0].c.center.x == 15 mm, "15 mm pitch"
    assert top.pegs[11].c.center.y - top.pegs[0].c.center.y == 15 mm, "15 mm rows"
    assert top.peg.c.center.x - top.body.bb.left == 30 mm, "30 from the left edge"
    assert top.peg.c.center.y - top.body.bb.bottom == 30 mm, "30 from the bottom edge"
    assert top.body.bb.right - top.pegs[120].c.center.x >= 10 mm, "grid inside the board"
    assert len(top.numbers.col) == 11 and len(top.numbers.row) == 11, "0 to 10 each way"
}
