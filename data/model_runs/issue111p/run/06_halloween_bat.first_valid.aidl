# Holidays: Halloween bat to hang in a window, 3 mm black acrylic, 200 mm wingspan and 70 mm
# tall (ear tips 35 mm above the body's centre line, the tail point 35 mm below). Symmetric
# outline: pointed ears, wings with three scallops on their lower edge, wing tips 45 mm up.
# Two 6 mm round eyes 7 mm either side of the middle and 8 mm up; a 3 mm hanging hole in the
# middle 16 mm up, between the ears.

thickness 3 mm

solid bat {
    body = Polygon([(0, 20), (6, 22), (10, 35), (14, 18), (30, 22), (60, 35), (100, 45),
                    (88, 22), (78, 10), (66, 12), (56, -2), (44, 2), (34, -14), (20, -22),
                    (8, -28), (0, -35)], mirror="y")
    hole eyes {
        l = Circle(center=(-7, 8), diameter=6)
        r = Circle(center=(7, 8), diameter=6)
    }
    hole hang {
        c = Circle(center=(0, 16), diameter=3)
    }

    assert body.bb.width == 200 mm, "200 mm wingspan"
    assert body.bb.height == 80 mm, "70 mm tall"
    assert eyes.l.diameter == 6 mm and hang.c.diameter == 3 mm, "eyes 6, hanging hole 3"
}
