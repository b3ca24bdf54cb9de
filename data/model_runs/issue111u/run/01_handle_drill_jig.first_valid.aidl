# Workshop: a cabinet-handle drilling template, 3 mm acrylic. Plate 200 x 50 mm, corners R3.
# Three rows of two 4 mm drill holes for handles of 96, 128 and 160 mm hole spacing, each pair
# centred on the plate's vertical centre line; rows 14 mm apart (160 at the top, 14 mm above the
# middle; 128 in the middle; 96 14 mm below). Each row's spacing engraved ("96", "128", "160",
# 4 mm) between its holes. A V-notch 6 mm wide, 4 mm deep in the middle of the top edge to line
# the template up with the door's centre mark.

thickness 3 mm

param spacings = [160, 128, 96]
param hole_d = 4 mm, min = 3 mm, max = 6 mm
param row_pitch = 14 mm, min = 10 mm, max = 16 mm

solid jig {
    plate = RoundedRectangle(center=(0, 0), width=200, height=50, corner_radius=3)

    hole drill {
        for i in range(3) {
            l = Circle(center=(-spacings[i] / 2, (1 - i) * row_pitch), diameter=hole_d)
            r = Circle(center=(spacings[i] / 2, (1 - i) * row_pitch), diameter=hole_d)
        }
    }

    hole notch {
        v = Triangle(center=(0, 23), base=6, height=4, rotation=180 deg)
    }
    AlignTop(notch, plate)

    drawing labels {
        for i in range(3) {
            t = Text(str(spacings[i]), ((0), (1 - i) * row_pitch), size=4, valign="middle")
        }
    }

    assert plate.bb.width == 200 mm and plate.bb.height == 50 mm, "plate 200 x 50"
    assert drill.r[0].center.x - drill.l[0].center.x == 160 mm, "top row 160"
    assert drill.r[1].center.x - drill.l[1].center.x == 128 mm, "middle row 128"
    assert drill.r[2].center.x - drill.l[2].center.x == 96 mm, "bottom row 96"
    assert drill.l[0].center.y - drill.l[1].center.y == 14 mm, "rows 14 apart"
    assert notch.bb.width == 6 mm and notch.bb.height == 4 mm, "notch 6 x 4"
    assert notch.bb.top == plate.bb.top, "notch in the top edge"
}
