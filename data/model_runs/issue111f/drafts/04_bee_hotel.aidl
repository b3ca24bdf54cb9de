# Bee hotel front panel (garden). Full sizes: 6 mm ply, a house outline 160 mm wide and
# 200 mm high: a 160 x 150 mm body with a gable roof (a triangle 160 mm at its base, 50 mm
# high) standing on its top edge. A honeycomb of 64 hexagonal holes for 12 mm nesting tubes:
# hexagons 12 mm across flats, pointy top and bottom (flats left and right), 8 rows of 8,
# 15 mm from a hole's centre to the next in a row (3 mm walls), rows 15 * sqrt(3) / 2 mm
# apart, every second row shifted 7.5 mm right; the honeycomb centred in the 160 x 150 body.
# Four 4 mm screw holes countersunk 8 mm, 8 mm in from each corner of the body (x and y).
# "BEE HOTEL" engraved 8 mm high in the roof, centred, its baseline 10 mm above the body.

units mm
thickness 6 mm

solid front {
    body = Rectangle(center=(0, 0), width=160, height=150)
    roof = Triangle(center=(0, 100), base=160, height=50)
    Above(roof, body)
    AlignCenterX(roof, body)

    hole comb {
        hole cell {
            h = RegularPolygon(center=(-56.25, -45.47), across_flats=12, sides=6, rotation=30 deg)
        }
        even = GridPattern(cell, 4, 8, col_spacing=15, row_spacing=15 * sqrt(3))
        hole shifted {
            h = RegularPolygon(center=(-48.75, -32.48), across_flats=12, sides=6, rotation=30 deg)
        }
        odd = GridPattern(shifted, 4, 8, col_spacing=15, row_spacing=15 * sqrt(3))
        At(shifted.h.center, cell.h.center, dx=7.5, dy=15 * sqrt(3) / 2)
    }
    CenterInside(comb, body)

    hole screws {
        s = Circle(center=(-72, -67), diameter=4)
    }
    CornerPattern(screws, body, inset=8)
    Countersink(screws, diameter=8)

    drawing sign {
        t = Text("BEE HOTEL", position=(0, 85), size=8)
    }
    AlignCenterX(sign, body)
    sign.t.position.y == body.bb.top + 10

    assert body.width == 160 mm and body.height == 150 mm, "body 160 x 150"
    assert roof.bb.width == 160 mm and roof.bb.height == 50 mm, "roof 160 base, 50 high"
    assert roof.bb.bottom == body.bb.top, "roof on the body"
    assert front.bb.width == 160 mm and front.bb.height == 200 mm, "outline 160 x 200"
    assert len(comb.even) + len(comb.odd) == 64, "64 cells"
    assert comb.cell.h.bb.width == 12 mm, "12 mm across flats"
    assert comb.shifted.h.center.x - comb.cell.h.center.x == 7.5 mm, "second row shifted 7.5"
    assert abs(comb.bb.center_x - body.bb.center_x) < 0.01 mm, "honeycomb centred across"
    assert abs(comb.bb.center_y - body.bb.center_y) < 0.01 mm, "honeycomb centred up and down"
    assert comb.bb.left - body.bb.left > 12 mm, "screw heads clear of the honeycomb"
    assert screws.s.diameter == 4 mm, "4 mm screws"
    assert screws.s.center.x - body.bb.left == 8 mm, "screws 8 mm in (x)"
    assert screws.s.center.y - body.bb.bottom == 8 mm, "screws 8 mm in (y)"
    assert sign.t.size == 8 mm, "sign 8 mm"
    assert sign.t.position.y - body.bb.top == 10 mm, "sign 10 mm above the body"
}
