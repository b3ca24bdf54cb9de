# Kitchen herb stripper: a plate 150 x 60 mm, 4 mm plywood, corners R8.
# Eight stripping holes in one row, diameters 3, 4, 5, 6, 7, 8, 10 and 12 mm, centres
# 15 mm apart, the row of centres centred left-right on the plate, centres 24 mm above
# the bottom edge. Each hole's diameter engraved under it (stroke text 4 mm high,
# baseline 8 mm above the bottom edge, centred under its hole). A 6 mm hanging hole,
# its centre 10 mm from the top edge and 10 mm from the right edge. "HERBS" engraved
# 6 mm high, centred left-right, its top 6 mm below the top edge.

units mm
thickness 4 mm

sizes = [3, 4, 5, 6, 7, 8, 10, 12]
pitch = 15 mm

solid stripper {
    plate = RoundedRectangle(center=(0, 0), width=150, height=60, corner_radius=8)

    hole strip {
        for i in range(len(sizes)) {
            h = Circle(center=((i - 3.5) * pitch, -6), diameter=sizes[i])
        }
    }

    hole hang {
        c = Circle(center=(65, 20), diameter=6)
    }

    drawing labels {
        for i in range(len(sizes)) {
            t = Text(str(sizes[i]), ((i - 3.5) * pitch, -22), size=4)
        }
    }

    drawing title {
        word = Text("HERBS", (0, 18), size=6)
    }

    # the request's numbers
    assert plate.width == 150 mm and plate.height == 60 mm, "plate 150 x 60"
    assert len(strip.h) == 8, "eight stripping holes"
    assert strip.h[0].diameter == 3 mm and strip.h[7].diameter == 12 mm, "3 to 12 mm"
    assert strip.h[6].diameter == 10 mm, "the seventh hole is 10 mm"
    assert strip.h[1].center.x - strip.h[0].center.x == 15 mm, "centres 15 apart"
    assert strip.h[7].center.x - strip.h[6].center.x == 15 mm, "centres 15 apart"
    assert strip.h[0].center.x + strip.h[7].center.x == 2 * plate.center.x, "row centred"
    assert strip.h[0].center.y - plate.bb.bottom == 24 mm, "centres 24 above the bottom"
    assert hang.c.diameter == 6 mm, "6 mm hanging hole"
    assert plate.bb.right - hang.c.center.x == 10 mm, "10 from the right edge"
    assert plate.bb.top - hang.c.center.y == 10 mm, "10 from the top edge"
    assert labels.t[0].position.y - plate.bb.bottom == 8 mm, "labels' baseline 8 above the bottom"
    assert labels.t[7].position.x == strip.h[7].center.x, "label under its hole"
    assert title.bb.center_x == plate.center.x, "title centred"
    assert plate.bb.top - title.bb.top == 6 mm, "title's top 6 below the top edge"
    assert labels.bb.top < strip.bb.bottom, "labels below the holes"
}
