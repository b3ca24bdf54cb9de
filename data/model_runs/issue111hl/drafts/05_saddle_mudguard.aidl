# Request (sport): a clip-on saddle mudguard ("ass saver") for my road bike, cut from 1 mm
# polypropylene. A smooth symmetric tongue 300 mm long: a 36 mm wide front tab (42 mm
# long, sharp corners) that tucks up under the saddle's nose side, wings 68 mm across where
# it clips to the rails, a 48 mm waist, widening to 96 mm near the rounded tail. The rails
# (42 mm apart, centre to centre) snap into two 6.5 mm notches cut in from the wings' edges
# 20 mm behind the tab. An engraved fold line across the tab's root; two 4 mm holes in the
# tab for a backup zip tie, 20 mm apart; "RIDE DRY" cut through as bold stencil letters,
# 14 mm high, reading along the tail.

units mm
thickness 1 mm

half = [(0, 150), (18, 150), (18, 108), (32, 100), (34, 72), (24, 50), (30, 0),
        (45, -70), (48, -115), (30, -143), (0, -150)]

solid mudguard {
    outline = Spline(mirror(half, about="y"), closed=true, corners=[1, 2, 18, 19])
    hole rails {
        r = Slot(start=(21, 88), end=(42, 88), width=6.5)
        l = Slot(start=(-21, 88), end=(-42, 88), width=6.5)
    }
    hole tie {
        a = Circle(center=(-10, 130), diameter=4)
        b = Circle(center=(10, 130), diameter=4)
    }
    hole word {
        w = Text("RIDE DRY", (0, -60), size=14, font="sans:Bold", valign="middle",
                 rotation=90, stencil=true)
    }
    drawing fold {
        f = Line((-18, 108), (18, 108))
    }
    Fixed(outline)

    # the request's numbers
    assert outline.points[0].y - outline.points[10].y == 300 mm, "300 mm long"
    assert outline.points[1].x - outline.points[19].x == 36 mm, "36 mm tab"
    assert outline.points[1].y - outline.points[2].y == 42 mm, "42 mm tab"
    assert rails.r.start.x - rails.l.start.x == 42 mm, "rails 42 mm apart"
    assert rails.r.width == 6.5 mm, "6.5 mm notches"
    assert outline.points[2].y - rails.r.start.y == 20 mm, "notches 20 mm behind the tab"
    assert tie.b.center.x - tie.a.center.x == 20 mm, "tie holes 20 mm apart"
    assert distance(word, rails) >= 5 mm, "word clear of the notches"
    assert word.bb.bottom - outline.bb.bottom >= 10 mm, "word inside the tail"
}
