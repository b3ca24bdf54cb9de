# Trail sign (signs, camping): an arrow-shaped signpost blade 300 x 70 mm of 6 mm plywood,
# pointing right: square left end with corners R4, the last 35 mm tapering to a point at mid
# height. "LAKE" in sans Bold 28 mm high engraved (filled), starting 40 mm from the left end;
# "2.5 km" in sans 14 mm high engraved (filled), ending 255 mm from the left end; both on one
# baseline 21 mm above the bottom. An engraved border line 5 mm inside the outline (mitred).
# Two 5 mm screw holes for the post, 20 mm from the left end, 18 mm from the top and from the
# bottom, countersunk 10 mm.
units mm
thickness 6 mm

OUTLINE = [(0, 0), (265, 0), (300, 35), (265, 70), (0, 70)]

solid sign {
    body = Polygon(OUTLINE)
    Fillet([body.points[0], body.points[4]], 4)

    hole screws {
        a = Circle(center=(20, 18), diameter=5)
        b = Circle(center=(20, 52), diameter=5)
    }
    Countersink(screws, diameter=10)

    drawing words {
        place = Text("LAKE", (40, 21), size=28, font="sans:Bold", fill=true, anchor="start")
        dist = Text("2.5 km", (255, 21), size=14, font="sans", fill=true, anchor="end")
    }

    drawing border {
        line = Inset(Polygon(OUTLINE), 5, join="miter")
    }

    assert body.bb.width == 300 mm and body.bb.height == 70 mm, "blade 300 x 70"
    assert body.points[2].x - body.points[1].x == 35 mm, "point 35 long"
    assert body.points[2].y - body.bb.bottom == 35 mm, "point at mid height"
    assert screws.a.center.x - body.bb.left == 20 mm and screws.b.center.x - body.bb.left == 20 mm, "screws 20 in"
    assert screws.a.center.y - body.bb.bottom == 18 mm and body.bb.top - screws.b.center.y == 18 mm, "screws 18 from the edges"
    assert words.place.position.x - body.bb.left == 40 mm, "LAKE 40 in"
    assert words.dist.position.x - body.bb.left == 255 mm, "2.5 km ends 255 in"
    assert words.place.position.y - body.bb.bottom == 21 mm, "baseline 21 up"
}
