# Request (parties): a "pin the tail on the donkey" game for a 6th birthday, from 3 mm ply.
# Board 420 x 300 mm with 10 mm corner radii and two 6 mm hanging holes 15 mm in from the top
# corners; the title "PIN THE TAIL ON THE DONKEY" engraved filled in bold serif at the top,
# at most 380 mm wide; a donkey facing left (body about 180 x 100 mm, neck, head, two long
# ears, four legs) engraved filled in the middle, and a 12 mm target circle engraved at its
# rump where the tail belongs. Four tails cut out as separate pieces: a strip 80 mm long,
# 10 mm wide at the top tapering to 6 mm, ending in a 7-point tuft 32 mm across, a 1.5 mm
# hole 6 mm below the top for the drawing pin, and the player's number 1-4 engraved on the
# tuft.

units mm
thickness 3 mm
kerf 0.1 mm

board_w = 420 mm
board_h = 300 mm
tails = 4

def tail(n=1) -> solid {
    strip = Polygon([(-5, 0), (5, 0), (3, -80), (-3, -80)])
    tuft = Star(center=(0, -92), points=7, outer_radius=16, inner_radius=9)
    hole pin { c = Circle(center=(0, -6), diameter=1.5) }
    drawing num { t = Text(str(n), position=(0, -93), size=8, valign="middle") }
}

assembly game {
    solid board {
        panel = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=10)
        Fixed(panel)
        hole hang_l { c = Circle(center=(-board_w / 2 + 15 mm, board_h / 2 - 15 mm), diameter=6) }
        hole hang_r { c = Circle(center=(board_w / 2 - 15 mm, board_h / 2 - 15 mm), diameter=6) }
        drawing title {
            t = Text("PIN THE TAIL ON THE DONKEY", position=(0, board_h / 2 - 30 mm), size=18,
                     font="serif:Bold", valign="middle", max_width=380 mm, fill=true)
        }
        # FIX after the first valid program: the donkey was ten overlapping filled shapes,
        # each its own fill path (the picture showed the overlaps darker: scanned twice, or
        # left blank by a fill that treats overlaps even-odd); now one closed silhouette,
        # straight legs and sharp ear tips by corners=
        drawing donkey {
            body = Spline([(-140, 20), (-141, 36), (-118, 56), (-98, 76), (-100, 128),
                           (-86, 84), (-74, 124), (-72, 74), (-56, 48), (-36, 30), (20, 32),
                           (80, 30), (108, 8), (104, -35), (94, -110), (78, -110), (74, -66),
                           (66, -66), (62, -110), (48, -110), (46, -62), (0, -72), (-38, -64),
                           (-40, -110), (-54, -110), (-56, -68), (-62, -68), (-64, -110),
                           (-78, -110), (-74, -45), (-80, -5), (-100, 4), (-125, 10)],
                          closed=true, fill=true,
                          corners=[4, 5, 6, 7, 14, 15, 16, 17, 18, 19, 20, 22, 23, 24, 25, 26,
                                   27, 28])
            target = Circle(center=(112, -5), diameter=12)
        }
        # the donkey hangs 8 mm under the title
        board.donkey.bb.top == title.bb.bottom - 8 mm
    }
    for i in range(tails) {
        t = tail(n=i + 1)
    }
    RightOf(t[0], board, gap=15)
    AlignTop(t[0], board)
    for i in range(1, tails) {
        RightOf(t[i], t[i - 1], gap=8)
        AlignTop(t[i], t[0])
    }

    assert board.panel.width == 420 mm and board.panel.height == 300 mm, "board 420 x 300"
    assert board.title.t.bb.width <= 380 mm, "title at most 380 wide"
    assert len(t) == 4, "four tails"
    assert t[0].strip.bb.height == 80 mm, "strip 80 long"
    assert t[0].tuft.outer_radius * 2 == 32 mm, "tuft 32 across"
    assert abs((board.donkey.body.points[12].x - board.donkey.body.points[30].x) - 180 mm) < 15 mm, "body about 180 long"
    assert board.donkey.bb.top < board.title.bb.bottom - 5 mm, "donkey clear of the title"
    assert board.donkey.bb.bottom > board.panel.bb.bottom + 10 mm, "donkey on the board"
}
