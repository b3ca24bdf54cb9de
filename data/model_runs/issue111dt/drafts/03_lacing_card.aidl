# Request: a lacing card for a three-year-old, in 4 mm poplar ply: a turtle seen from above,
# about 170 x 130 mm. An oval shell 120 x 90 mm, a round head 40 mm across at the front
# (pointing +x), four oval flippers (44 x 20 mm) at the shell's four diagonals angled 35 deg,
# and a short pointed tail; all one piece with every corner rounded R3 so nothing is sharp.
# 18 lacing holes, 6 mm, on an oval 100 x 70 mm centred in the shell (10 mm in from its
# edge), at least 12 mm apart centre to centre. The shell's plates engraved as a cluster of
# seven hexagons (10 mm corner radius) in the middle; two 5 mm eyes engraved filled.

units mm
thickness 4 mm

holes_n = 18
ring_rx = 50 mm
ring_ry = 35 mm

solid turtle {
    # E0407: Fillet cannot round where an Ellipse (or a Spline) meets another curve, so the
    # shell is a 72-sided Polygon on the 120 x 90 oval (chords 5 mm long, 0.05 mm off it)
    # and the flippers are Slots
    shell = Polygon([(60 * cos(i * 5 deg), 45 * sin(i * 5 deg)) for i in range(72)])
    head = Circle(center=(72, 0), diameter=40)
    flipper_fr = Slot(center=(38, 40), length=44, width=20, rotation=35 deg)
    flipper_fl = Slot(center=(38, -40), length=44, width=20, rotation=-35 deg)
    flipper_br = Slot(center=(-38, 40), length=44, width=20, rotation=-35 deg)
    flipper_bl = Slot(center=(-38, -40), length=44, width=20, rotation=35 deg)
    tail = Polygon([(-55, 7), (-55, -7), (-76, 0)])

    hole lacing {
        for i in range(holes_n) {
            c = Circle(center=(ring_rx * cos(i * 360 deg / holes_n),
                               ring_ry * sin(i * 360 deg / holes_n)), diameter=6)
        }
    }

    # W0513: neighbouring hexagons shared edges (burnt twice): the 10 mm hexagons on a
    # 19 mm pitch instead of 17.32 leave a 1.7 mm groove between the plates
    drawing plates {
        mid = RegularPolygon(center=(0, 0), radius=10, sides=6)
        for k in range(6) {
            p = RegularPolygon(center=(19 * cos(30 deg + k * 60 deg),
                                       19 * sin(30 deg + k * 60 deg)), radius=10, sides=6)
        }
    }

    drawing eyes {
        e1 = Circle(center=(82, 8), diameter=5, fill=true)
        e2 = Circle(center=(82, -8), diameter=5, fill=true)
    }

    Fillet(3 mm)

    # the request's numbers
    assert len(lacing.c) == 18, "18 lacing holes"
    assert shell.points[0].x - shell.points[36].x == 120 mm and
        shell.points[18].y - shell.points[54].y == 90 mm, "shell 120 x 90"
    assert head.diameter == 40 mm, "head 40 mm"
    assert lacing.bb.width == 100 mm + 6 mm and lacing.bb.height <= 70 mm + 6 mm,
        "holes on a 100 x 70 oval"
    assert min([distance(lacing.c[i].center, lacing.c[(i + 1) % holes_n].center)
                for i in range(holes_n)]) >= 12 mm, "holes at least 12 mm apart"
    assert turtle.bb.width <= 175 mm and turtle.bb.height <= 135 mm, "about 170 x 130"
}
