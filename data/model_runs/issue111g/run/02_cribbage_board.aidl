# Cribbage board (short 30-hole game), 6 mm plywood: 260 x 70 mm with 6 mm corner radii.
# Three tracks (one per player) of 30 peg holes 3.2 mm diameter, in 6 groups of 5: holes 6 mm
# apart within a group, 10 mm from the last hole of a group to the first of the next.
# The tracks are 12 mm apart, the middle track 8 mm below the board's centre line; each
# track's 30 holes are centred left-right on the board, and each track has a start hole
# (3.2 mm) 15 mm left of its first hole.
# "CRIBBAGE" in Noto Sans Bold, 10 mm cap height, fill-engraved, centred left-right, its middle
# 12 mm below the top edge.
# Two M3 countersunk screw holes (3.5 mm, 7 mm heads) 10 mm in from the bottom and side edges
# at the two bottom corners, to screw the board to a base.
units mm
thickness 6 mm

solid board {
    body = RoundedRectangle(center=(0, 0), width=260, height=70, corner_radius=6)
    Fixed(body)

    hole track {
        for i in range(30) {
            peg = Circle(center=(-97 + (i % 5) * 6 + (i // 5) * 34, 4), diameter=3.2)
        }
        start = Circle(center=(-97 - 15, 4), diameter=3.2)
    }
    tracks = LinearPattern(track, 3, (0, -12))

    hole screw {
        c = Circle(center=(-120, -25), diameter=3.5)
    }
    screws = LinearPattern(screw, 2, (240, 0))
    Countersink(screws, diameter=7)

    drawing title {
        t = Text("CRIBBAGE", position=(0, 23), size=10, font="sans:Bold", valign="middle",
                 fill=true)
    }

    # the request's numbers
    assert body.width == 260 mm and body.height == 70 mm, "board size"
    assert len(tracks) == 3, "three tracks"
    assert len(track.peg) == 30, "30 holes a track"
    assert track.peg[0].diameter == 3.2 mm and track.start.diameter == 3.2 mm, "peg holes"
    assert track.peg[1].center.x - track.peg[0].center.x == 6 mm, "6 mm within a group"
    assert track.peg[5].center.x - track.peg[4].center.x == 10 mm, "10 mm between groups"
    assert track.peg[29].center.x - track.peg[25].center.x == 24 mm, "last group of 5"
    assert (track.peg[0].center.x + track.peg[29].center.x) / 2 == body.center.x, "centred"
    assert tracks[0].peg[0].center.y - tracks[1].peg[0].center.y == 12 mm, "tracks 12 mm apart"
    assert tracks[1].peg[0].center.y - tracks[2].peg[0].center.y == 12 mm, "tracks 12 mm apart"
    assert body.center.y - tracks[1].peg[0].center.y == 8 mm, "middle track 8 mm below"
    assert track.peg[0].center.x - track.start.center.x == 15 mm, "start hole 15 mm left"
    assert abs(title.t.bb.center_x - body.center.x) < 0.01 mm, "title centred"
    assert body.bb.top - title.t.bb.center_y == 12 mm, "title 12 mm below the top"
    assert screw.c.center.x - body.bb.left == 10 mm, "screw 10 mm from the side"
    assert screw.c.center.y - body.bb.bottom == 10 mm, "screw 10 mm from the bottom"
    assert body.bb.right - screws[1].c.center.x == 10 mm, "other screw 10 mm from the side"
    assert len(screws) == 2 and screw.c.diameter == 3.5 mm, "two M3 holes"
}
