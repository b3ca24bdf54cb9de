# Camping: flat sand/snow tent stake, 6 mm plywood, 180 mm long. Outline symmetric about the
# vertical centre line: a head 40 mm wide and 25 mm tall at the top, then shoulders narrowing to
# 24 mm wide 40 mm below the top, then tapering straight to the point 180 mm below the top.
# A guy-line notch in each side of the head: a 5 mm wide slot sloping down inward, from past
# the head's edge at 8 mm below the top to its end centre 10 mm from the centre line and 16 mm
# below the top. A 6 mm lanyard hole on the centre line 8 mm below the top. Three grip holes on
# the centre line, 8, 7 and 6 mm, at 55, 75 and 95 mm below the top. All outline corners
# rounded 2 mm, except the point: rounded 0.5 mm (a 2 mm round on its
# 10 deg point would take 21 mm off the length).

thickness 6 mm

solid stake {
    body = Polygon([(0, 0), (20, 0), (20, -25), (12, -40), (0, -180)], mirror="y")
    hole notches {
        right = Slot(start=(24, -8), end=(10, -16), width=5)
        left = Slot(start=(-24, -8), end=(-10, -16), width=5)
    }
    hole lanyard {
        c = Circle(center=(0, -8), diameter=6)
    }
    hole grips {
        g1 = Circle(center=(0, -55), diameter=8)
        g2 = Circle(center=(0, -75), diameter=7)
        g3 = Circle(center=(0, -95), diameter=6)
    }
    Fillet(2)
    Fillet((0, -180), 0.5)

    assert body.bb.width == 40 mm, "head 40 mm wide"
    assert body.bb.height == 180 mm, "180 mm long"
    assert self.bb.height > 179.5 mm, "the rounded point keeps the length"
    assert body.bb.top - notches.right.start.y == 8 mm, "notch starts 8 mm below the top"
    assert lanyard.c.diameter == 6 mm and body.bb.top - lanyard.c.center.y == 8 mm, "lanyard hole 8 mm below the top"
    assert notches.right.width == 5 mm, "5 mm notches"
    assert notches.right.end.x - body.bb.center_x == 10 mm, "notch ends 10 mm from the centre line"
    assert body.bb.top - notches.right.end.y == 16 mm, "notch ends 16 mm below the top"
    assert notches.right.start.x > body.bb.right, "notch opens past the edge"
    assert grips.g1.diameter == 8 mm and grips.g2.diameter == 7 mm and grips.g3.diameter == 6 mm, "grip holes 8, 7, 6"
    assert body.bb.top - grips.g1.center.y == 55 mm, "grip 1 at 55"
    assert body.bb.top - grips.g2.center.y == 75 mm, "grip 2 at 75"
    assert body.bb.top - grips.g3.center.y == 95 mm, "grip 3 at 95"
    assert grips.g3.center.x == body.bb.center_x, "grips on the centre line"
}
