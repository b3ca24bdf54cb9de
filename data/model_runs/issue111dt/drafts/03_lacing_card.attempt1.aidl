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
    shell = Ellipse(center=(0, 0), rx=60, ry=45)
    head = Circle(center=(72, 0), diameter=40)
    flipper_fr = Ellipse(center=(38, 40), rx=22, ry=10, rotation=35 deg)
    flipper_fl = Ellipse(center=(38, -40), rx=22, ry=10, rotation=-35 deg)
    flipper_br = Ellipse(center=(-38, 40), rx=22, ry=10, rotation=-35 deg)
    flipper_bl = Ellipse(center=(-38, -40), rx=22, ry=10, rotation=35 deg)
    tail = Polygon([(-55, 7), (-55, -7), (-76, 0)])

    hole lacing {
        for i in range(holes_n) {
            c = Circle(center=(ring_rx * cos(i * 360 deg / holes_n),
                               ring_ry * sin(i * 360 deg / holes_n)), diameter=6)
        }
    }

    drawing plates {
        mid = RegularPolygon(center=(0, 0), radius=10, sides=6)
        for k in range(6) {
            p = RegularPolygon(center=(17.32 * cos(30 deg + k * 60 deg),
                                       17.32 * sin(30 deg + k * 60 deg)), radius=10, sides=6)
        }
    }

    drawing eyes {
        e1 = Circle(center=(82, 8), diameter=5, fill=true)
        e2 = Circle(center=(82, -8), diameter=5, fill=true)
    }

    Fillet(3 mm)

    # the request's numbers
    assert len(lacing.c) == 18, "18 lacing holes"
    assert shell.rx * 2 == 120 mm and shell.ry * 2 == 90 mm, "shell 120 x 90"
    assert head.diameter == 40 mm, "head 40 mm"
    assert lacing.bb.width == 100 mm + 6 mm and lacing.bb.height <= 70 mm + 6 mm,
        "holes on a 100 x 70 oval"
    assert min([distance(lacing.c[i].center, lacing.c[(i + 1) % holes_n].center)
                for i in range(holes_n)]) >= 12 mm, "holes at least 12 mm apart"
    assert turtle.bb.width <= 175 mm and turtle.bb.height <= 135 mm, "about 170 x 130"
}
