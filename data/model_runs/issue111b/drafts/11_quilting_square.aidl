# Quilting square ruler, 1/8 in clear acrylic, in inches: 6.5 x 6.5 in with 1/8 in corner radii.
# Engraved: a grid line every inch (x = 1..6 and y = 1..6 from the bottom-left corner), each
# stopping 0.1 in short of the edges; 1/4 in seam lines 0.25 in inside the top and right edges
# (also 0.1 in short of the edges); a 45-degree diagonal from corner to corner, 0.1 in short
# of each corner; the inch numbers 1..6 along the bottom, 0.15 in tall, just left of their
# line (right end 0.05 in left of it), baseline 0.2 in above the bottom edge. A 1/4 in hanging
# hole centered in the top-left inch square.

units in
thickness 0.125 in

param side = 6.5 in, min = 4.5 in, max = 12.5 in

solid ruler {
    plate = RoundedRectangle(bottom_left=(0, 0), width=side, height=side, corner_radius=0.125)

    hole hang {
        c = Circle(center=(0.5, side - 1 in), diameter=0.25)
    }

    drawing marks {
        for i in range(1, 7) {
            v = Line((i, 0.1), (i, side - 0.1 in))
            h = Line((0.1, i), (side - 0.1 in, i))
            n = Text(str(i), position=(i - 0.05 in, 0.2), size=0.15, anchor="end")
        }
        seam_v = Line((side - 0.25 in, 0.1), (side - 0.25 in, side - 0.1 in))
        seam_h = Line((0.1, side - 0.25 in), (side - 0.1 in, side - 0.25 in))
        diag = Line((0.1, 0.1), (side - 0.1 in, side - 0.1 in))
    }

    assert abs(plate.bb.width - 6.5 in) < 0.001 in and abs(plate.bb.height - 6.5 in) < 0.001 in, "6.5 in square"
    assert len(marks.v) == 6 and len(marks.h) == 6, "a line every inch, 1..6"
    assert abs(marks.v[1].start.x - marks.v[0].start.x - 1 in) < 0.001 in, "lines 1 in apart"
    assert abs(plate.bb.right - marks.seam_v.start.x - 0.25 in) < 0.001 in, "seam 1/4 in from the right edge"
    assert abs(plate.bb.top - marks.seam_h.start.y - 0.25 in) < 0.001 in, "seam 1/4 in from the top edge"
    assert abs(marks.diag.angle - 45 deg) < 0.01 deg, "45-degree diagonal"
    assert abs(hang.c.diameter - 0.25 in) < 0.001 in, "1/4 in hole"
}
