# School geometry stencil, 3 mm acrylic: 180 x 90 mm with 5 mm corner radii.
# Five shapes cut out in a row, their centres 34 mm apart (the middle one on the vertical centre
# line), 12 mm above the horizontal centre line: a circle 28 mm diameter, a square 26 mm, an
# equilateral triangle of 30 mm sides pointing up (centred on its box), a regular hexagon 28 mm
# across flats (flats top and bottom), a five-pointed star of 15 mm outer and 6 mm inner radius.
# Under each shape its name engraved in single strokes 3.5 mm high, centred 20 mm below the
# shape's centre: CIRCLE, SQUARE, TRIANGLE, HEXAGON, STAR.
# Along the bottom edge a 150 mm scale, centred: a tick every 5 mm from the edge up, 3 mm long,
# 6 mm at every whole centimetre; the numbers 0 to 15 (2.5 mm high) centred 9 mm above the edge
# over the centimetre ticks.
# A 6 mm hanging hole 8 mm in from the top and right edges.
units mm
thickness 3 mm

pitch = 34 mm
row_y = 12 mm

solid stencil {
    body = RoundedRectangle(center=(0, 0), width=180, height=90, corner_radius=5)
    Fixed(body)

    hole shapes {
        circle = Circle(center=(-2 * pitch, row_y), diameter=28)
        square = Rectangle(center=(-pitch, row_y), width=26, height=26)
        triangle = Triangle(center=(0, row_y), base=30, height=30 * sqrt(3) / 2)
        hexagon = RegularPolygon(center=(pitch, row_y), across_flats=28, sides=6)
        star = Star(center=(2 * pitch, row_y), points=5, outer_radius=15, inner_radius=6)
    }
    hole hang {
        c = Circle(center=(82, 37), diameter=6)
    }

    drawing names {
        words = ["CIRCLE", "SQUARE", "TRIANGLE", "HEXAGON", "STAR"]
        for i in range(5) {
            name = Text(words[i], position=((i - 2) * pitch, row_y - 20), size=3.5,
                        valign="middle")
        }
    }

    drawing scale {
        for i in range(31) {
            tick = Line((-75 + 5 * i, -45), (-75 + 5 * i, -45 + (6 if i % 2 == 0 else 3)))
        }
        for k in range(16) {
            num = Text(str(k), position=(-75 + 10 * k, -45 + 9), size=2.5, valign="middle")
        }
    }

    # the request's numbers
    assert body.width == 180 mm and body.height == 90 mm, "stencil size"
    assert shapes.circle.diameter == 28 mm, "circle 28 mm"
    assert shapes.square.width == 26 mm and shapes.square.height == 26 mm, "square 26 mm"
    assert abs(shapes.triangle.ab.length - 30 mm) < 0.001 mm, "triangle side 30"
    assert abs(shapes.triangle.bc.length - 30 mm) < 0.001 mm, "equilateral"
    assert abs(shapes.hexagon.bb.height - 28 mm) < 0.001 mm, "hexagon 28 across flats"
    assert shapes.star.outer_radius == 15 mm and shapes.star.inner_radius == 6 mm, "star"
    assert shapes.square.center.x - shapes.circle.center.x == 34 mm, "34 mm apart"
    assert shapes.star.center.x - shapes.hexagon.center.x == 34 mm, "34 mm apart"
    assert shapes.triangle.center.x == body.center.x, "middle shape on the centre line"
    assert shapes.circle.center.y - body.center.y == 12 mm, "row 12 mm above the centre"
    assert len(names.name) == 5, "five names"
    assert shapes.hexagon.center.y - names.name[3].position.y == 20 mm, "names 20 mm below"
    assert len(scale.tick) == 31, "a tick every 5 mm over 150 mm"
    assert scale.tick[30].start.x - scale.tick[0].start.x == 150 mm, "150 mm scale"
    assert scale.tick[2].length == 6 mm and scale.tick[1].length == 3 mm, "tick lengths"
    assert (scale.tick[0].start.x + scale.tick[30].start.x) / 2 == body.center.x, "centred"
    assert len(scale.num) == 16, "0 to 15"
    assert body.bb.right - hang.c.center.x == 8 mm and body.bb.top - hang.c.center.y == 8 mm, "hang hole"
}
