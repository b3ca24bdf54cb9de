# Signs: a "laser in use" warning sign for the workshop door, 3 mm acrylic.
# Plate 200 x 150 mm, corner radius 8 mm. Four 4 mm screw holes, countersunk 8 mm, 10 mm in
# from each side at every corner. Engraved: an equilateral warning triangle, 90 mm sides,
# point up, drawn as a 4 mm band (its outer edge 90 mm), its top 10 mm below the plate's
# top, centred; inside it the laser symbol: a 12 mm circle at the triangle's incentre with
# 12 rays from R9 to R16, and a beam line from R16 leftwards to 4 mm short of the band.
# Below the triangle "CAUTION" in sans Bold, filled, 14 mm tall, and "LASER IN USE" 9 mm
# tall (strokes), both centred; CAUTION's middle 30 mm below the plate's centre line,
# LASER IN USE's middle 55 mm below it.

thickness 3 mm

solid sign {
    body = RoundedRectangle(center=(0, 0), width=200, height=150, corner_radius=8)

    hole screw {
        c = Circle(center=(-90, -65), diameter=4)
    }
    screws = CornerPattern(screw, body, inset=10)
    Countersink(screws, diameter=8)

    drawing hazard {
        edge = Triangle(center=(0, 26.03), base=90, height=77.94, construction=true)
        band = Shell(edge, -4, join="miter")
        dot = Circle(center=(0, 0), diameter=12)
        ray = Line((9, 0), (16, 0))
        rays = CircularPattern(ray, 12, dot.center)
        beam = Line((-16, 0), (-20, 0))
    }
    AlignCenterX(hazard.edge, body)
    body.bb.top - hazard.edge.bb.top == 10 mm
    Coincident(hazard.dot.center, hazard.edge.incenter)
    # the beam runs left from the rays' ends to 4 mm short of the band's inner edge
    hazard.beam.start.y == hazard.dot.center.y
    hazard.beam.end.y == hazard.dot.center.y
    hazard.beam.start.x == hazard.dot.center.x - 16 mm

    drawing words {
        caution = Text("CAUTION", (0, -30), size=14, font="sans:Bold", fill=true, valign="middle")
        laser = Text("LASER IN USE", (0, -55), size=9, valign="middle")
    }

    assert body.width == 200 mm and body.height == 150 mm, "plate 200 x 150"
    assert len(screws) == 4, "four screws"
    assert screw.c.diameter == 4 mm, "4 mm screws"
    assert screws[0].c.center.x - body.bb.left == 10 mm and screws[0].c.center.y - body.bb.bottom == 10 mm, "10 mm in from the corner"
    assert abs(hazard.edge.bb.width - 90 mm) < 0.01 mm, "90 mm triangle"
    assert body.bb.top - hazard.edge.bb.top == 10 mm, "triangle 10 mm below the top"
    assert hazard.dot.diameter == 12 mm, "12 mm circle"
    assert len(hazard.rays) == 12, "12 rays"
    assert hazard.ray.length == 7 mm, "rays from R9 to R16"
    assert words.caution.size == 14 mm and words.laser.size == 9 mm, "text sizes"
    assert hazard.bb.bottom > words.caution.bb.top + 3 mm, "triangle clear of CAUTION"
    assert words.caution.bb.bottom > words.laser.bb.top + 3 mm, "lines apart"
    assert words.laser.bb.bottom > body.bb.bottom + 5 mm, "text on the plate"
}
