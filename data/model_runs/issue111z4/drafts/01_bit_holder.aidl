# Workshop: a bench-top holder for 1/4 in hex screwdriver bits, 6 mm plywood.
# Plate 180 x 50 mm, corners R5. 2 rows x 10 columns of hexagonal holes 6.6 mm across
# flats (flats at top and bottom), columns 14 mm apart, rows 13 mm apart, the grid centred
# left-right, the top row's centres 12 mm below the top edge. Two 4.5 mm screw holes
# countersunk 9 mm (90 deg), 12 mm in from each end, centred in the height. Engraved label
# "1/4 IN HEX BITS", 5 mm tall, centred, its baseline 6 mm above the bottom edge.

units mm
thickness 6 mm

param cols = 10, min = 2, max = 11
param rows = 2, min = 1, max = 2
param pitch_x = 14 mm, min = 10 mm, max = 16 mm
param pitch_y = 13 mm, min = 10 mm, max = 16 mm

solid holder {
    plate = RoundedRectangle(center=(0, 0), width=180, height=50, corner_radius=5)

    hole bit {
        hex = RegularPolygon(center=(-60, -10), across_flats=6.6, sides=6)
    }
    bits = GridPattern(bit, rows, cols, (pitch_x, -pitch_y))
    # the grid is centred left-right; the top row (the original's row) 12 mm below the top edge
    bits[0].hex.center.x + bits[cols - 1].hex.center.x == 2 * plate.center.x
    VerticalDistance(bit.hex.center, plate.top.midpoint, 12)

    hole screw {
        c = Circle(center=(-78, 0), diameter=4.5)
    }
    screws = LinearPattern(screw, 2, (180 - 2 * 12, 0))
    HorizontalDistance(plate.left.midpoint, screw.c.center, 12)
    AlignCenterY(screw, plate)
    Countersink(screws, diameter=9)

    drawing label {
        t = Text("1/4 IN HEX BITS", position=(0, -19), size=5)
    }
    AlignCenterX(label, plate)
    VerticalDistance(plate.bottom.midpoint, label.t.position, 6)

    assert plate.bb.width == 180 mm and plate.bb.height == 50 mm, "plate 180 x 50"
    assert len(bits) == 20, "2 x 10 bit holes"
    assert bit.hex.bb.height == 6.6 mm, "6.6 mm across flats, flats top and bottom"
    assert bits[1].hex.center.x - bits[0].hex.center.x == 14 mm, "columns 14 mm apart"
    assert bits[0].hex.center.y - bits[cols].hex.center.y == 13 mm, "rows 13 mm apart"
    assert plate.bb.top - bit.hex.center.y == 12 mm, "top row 12 mm below the top edge"
    assert screw.c.center.x - plate.bb.left == 12 mm, "screws 12 mm in from the ends"
    assert len(screws) == 2, "two screws"
}
