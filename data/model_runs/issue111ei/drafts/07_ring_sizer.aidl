# Request (crafts): a ring sizer for my jewellery stall, cut from 3 mm clear acrylic on my
# laser (kerf 0.15 mm, so the holes must come out true). A plate 170 x 105 with R6 corners.
# Ten holes for US ring sizes 4 to 13 (diameter = 11.63 mm + 0.8128 mm x size), in two rows
# of five, 30 mm apart, size 4 to 8 across the top row (centres 22 mm above the middle),
# 9 to 13 across the bottom row (23 mm below the middle), the first column 60 mm left of the
# middle. Under each hole, engraved in plain strokes: the size (5 mm tall) with its baseline
# 3 + 5 mm under the largest hole's rim line, and the diameter to 0.1 mm (3 mm tall) 2 mm
# under that. Title RING SIZE (US) engraved, 6 mm, centred, baseline 43 mm above the middle.
# A 5 mm hanging hole 8 mm in from the top and left edges.

kerf 0.15 mm
thickness 3 mm

sizes = range(4, 14)
def ring_d(s) = 11.63 mm + 0.8128 mm * s
pitch = 30 mm
col0 = -60 mm
row_y = [22 mm, -23 mm]
r_max = ring_d(13) / 2

solid ring_sizer {
    plate = RoundedRectangle(center=(0, 0), width=170, height=105, corner_radius=6)
    for i in range(10) {
        hole h {
            c = Circle(center=(col0 + (i % 5) * pitch, row_y[i // 5]), diameter=ring_d(sizes[i]))
        }
    }
    hole hang { c = Circle(center=(-85 + 8, 52.5 - 8), diameter=5) }
    drawing labels {
        title = Text("RING SIZE (US)", position=(0, 43), size=6)
        for i in range(10) {
            n = Text(str(sizes[i]), position=(col0 + (i % 5) * pitch, row_y[i // 5] - r_max - 3 - 5),
                     size=5)
            d = Text(f"{ring_d(sizes[i]):.1f}",
                     position=(col0 + (i % 5) * pitch, row_y[i // 5] - r_max - 3 - 5 - 2 - 3),
                     size=3)
        }
    }

    # the request's numbers
    assert len(h) == 10, "ten sizes"
    assert abs(h[3].c.diameter - 17.32 mm) < 0.01 mm, "size 7 is 17.32 mm"
    assert abs(h[0].c.diameter - 14.88 mm) < 0.01 mm and abs(h[9].c.diameter - 22.20 mm) < 0.01 mm,
        "sizes 4 and 13"
    assert h[1].c.center.x - h[0].c.center.x == 30 mm, "30 mm apart"
    assert h[0].c.center.y - plate.center.y == 22 mm and h[5].c.center.y - plate.center.y == -23 mm,
        "rows 22 above and 23 below"
    assert plate.bb.width == 170 mm and plate.bb.height == 105 mm, "plate 170 x 105"
    assert distance(labels, h[9]) >= 1 mm, "labels clear of the holes"
    assert distance(labels, hang) >= 1 mm, "labels clear of the hanging hole"
    assert labels.bb.bottom - plate.bb.bottom >= 2 mm, "labels on the plate"
}
