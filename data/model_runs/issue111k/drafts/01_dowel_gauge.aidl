# Workshop dowel and drill sizing gauge: a 150 x 45 mm plate with 4 mm rounded corners, 3 mm
# plywood. A row of 7 test holes of 4, 5, 6, 8, 10, 12 and 16 mm diameter, centres 18 mm apart,
# the first 15 mm from the left end, all centres 18 mm above the bottom edge. Each hole's size
# engraved above it ("4" ... "16"), 5 mm text, baseline 32 mm above the bottom edge, centred
# over its hole. A 6 mm hanging hole 12 mm from the right end, centred in height.

thickness 3 mm

sizes = [4, 5, 6, 8, 10, 12, 16]

solid gauge {
    plate = RoundedRectangle(bottom_left=(0, 0), width=150, height=45, corner_radius=4)

    hole tests {
        for i in range(len(sizes)) {
            h = Circle(center=(15 + i * 18, 18), diameter=sizes[i])
        }
    }

    hole hang {
        eye = Circle(center=(150 - 12, 22.5), diameter=6)
    }

    drawing labels {
        for i in range(len(sizes)) {
            t = Text(str(sizes[i]), (15 + i * 18, 32), size=5)
        }
    }

    assert plate.width == 150 mm, "plate 150 mm long"
    assert plate.height == 45 mm, "plate 45 mm high"
    assert len(tests.h) == 7, "7 test holes"
    assert tests.h[0].diameter == 4 mm, "first hole 4 mm"
    assert tests.h[6].diameter == 16 mm, "last hole 16 mm"
    assert tests.h[0].center.x - plate.bb.left == 15 mm, "first hole 15 mm from the left end"
    assert tests.h[1].center.x - tests.h[0].center.x == 18 mm, "centres 18 mm apart"
    assert tests.h[6].center.x - tests.h[5].center.x == 18 mm, "centres 18 mm apart"
    assert tests.h[3].center.y - plate.bb.bottom == 18 mm, "centres 18 mm above the bottom"
    assert labels.t[0].position.y - plate.bb.bottom == 32 mm, "labels' baseline 32 mm up"
    assert labels.t[6].position.x == tests.h[6].center.x, "label over its hole"
    assert hang.eye.diameter == 6 mm, "hanging hole 6 mm"
    assert plate.bb.right - hang.eye.center.x == 12 mm, "hanging hole 12 mm from the right end"
    assert hang.eye.center.y == plate.bb.center_y, "hanging hole centred in height"
}
