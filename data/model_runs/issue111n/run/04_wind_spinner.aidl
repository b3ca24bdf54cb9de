# Garden: a wind spinner (hanging pinwheel disc) in 3 mm acrylic, 200 mm across.
# Eight curved slits 6 mm wide, each along an arc of radius 45 mm about a point 50 mm
# from the disc's centre, from 60 deg to 140 deg, repeated every 45 deg round the
# centre (a pinwheel); every slit stays at least 10 mm inside the rim. A hexagonal
# window 24 mm across flats in the middle. A 5 mm hanging hole, its centre 8 mm below
# the top of the disc.

units mm
thickness 3 mm

solid spinner {
    disc = Circle(center=(0, 0), diameter=200)

    hole vane {
        s = ArcSlot(center=(50, 0), radius=45, start_angle=60 deg, end_angle=140 deg, width=6)
    }
    vanes = CircularPattern(vane, 8, disc.center)

    hole window {
        hex = RegularPolygon(center=(0, 0), across_flats=24, sides=6)
    }
    Concentric(window.hex, disc)

    hole hang {
        c = Circle(center=(0, 92), diameter=5)
    }
    AlignCenterX(hang, disc)
    VerticalDistance(hang.c.center, disc.top, 8)

    # the request's numbers
    assert disc.diameter == 200 mm, "200 mm across"
    assert len(vanes) == 8, "eight slits"
    assert vane.s.width == 6 mm and vane.s.radius == 45 mm, "6 mm slits on R45 arcs"
    assert distance(vane.s.center, disc.center) == 50 mm, "arc centre 50 from the centre"
    assert distance(vane.s.end, disc.center) + 3 mm <= 100 mm - 10 mm, "outer end 10 inside the rim"
    assert distance(vane.s.start, disc.center) + 3 mm <= 100 mm - 10 mm, "inner end 10 inside the rim"
    assert window.hex.bb.height == 24 mm, "hexagon 24 across flats"
    assert hang.c.diameter == 5 mm, "5 mm hanging hole"
    assert disc.bb.top - hang.c.center.y == 8 mm, "hanging hole 8 below the top"
}
