# Tangram puzzle in a tray, 3 mm plywood. The puzzle: a 120 mm square cut by slits into the
# classic seven pieces (two large triangles, one medium, two small, a square and a
# parallelogram), no waste: the full diagonal; a line from the top-left corner to the center;
# a line from the middle of the bottom edge to the middle of the right edge; from the center
# to the middle of that line; from the diagonal's 3/4 point to the middle of the right edge;
# and the level line at a quarter height from the diagonal to the middle of the medium line.
# The tray: a 150 x 150 mm frame with R6 outer corners and a 121 mm square opening (0.5 mm
# play each side), "TANGRAM" engraved 6 mm tall, centered in the frame's bottom border.
# Frame and puzzle laid side by side, 5 mm apart.
units mm
thickness 3 mm

param s = 120 mm, min = 80 mm, max = 150 mm

assembly tangram {
    solid puzzle {
        sq = Rectangle(center=(0, 0), width=s, height=s)
        cut slits {
            diag = Line((-s / 2, -s / 2), (s / 2, s / 2))
            half = Line((-s / 2, s / 2), (0, 0))
            medium = Line((0, -s / 2), (s / 2, 0))
            sq_a = Line((0, 0), (s / 4, -s / 4))
            sq_b = Line((s / 4, s / 4), (s / 2, 0))
            par = Line((-s / 4, -s / 4), (s / 4, -s / 4))
        }
    }

    solid frame {
        outer = RoundedRectangle(center=(0, 0), width=150, height=150, corner_radius=6)
        hole opening {
            o = Rectangle(center=(0, 0), width=s + 1 mm, height=s + 1 mm)
        }
        CenterInside(opening, outer)
        drawing label {
            t = Text("TANGRAM", position=(0, 0), size=6, valign="middle")
        }
        AlignCenterX(label, outer)
        label.t.center.y == (outer.bb.bottom + opening.bb.bottom) / 2
    }
    RightOf(frame, puzzle, gap=5)
    AlignCenterY(frame, puzzle)

    assert puzzle.sq.width == 120 mm and puzzle.sq.height == 120 mm, "puzzle 120 mm square"
    assert frame.outer.width == 150 mm and frame.outer.height == 150 mm, "frame 150 x 150 mm"
    assert frame.opening.o.width == 121 mm, "opening 121 mm (0.5 mm play each side)"
    assert frame.opening.o.width - puzzle.sq.width == 2 * 0.5 mm, "0.5 mm play each side"
    assert frame.bb.left - puzzle.bb.right == 5 mm, "laid 5 mm apart"
    assert puzzle.slits.diag.length == 120 mm * sqrt(2), "full diagonal"
}
