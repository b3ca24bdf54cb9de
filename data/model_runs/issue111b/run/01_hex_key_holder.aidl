# Hex key (Allen key) holder plate: 130 x 40 mm, 3 mm plywood, R4 corners.
# Six hexagonal holes for keys of 2, 2.5, 3, 4, 5 and 6 mm (across flats + 0.2 mm clearance),
# in a row 18 mm apart centered on the plate, their centers 5 mm above the plate's center line;
# each key's size engraved 4 mm tall under its hole (top of the text 4 mm below the plate's
# center line); two 4 mm mounting holes on the center line, 7 mm from each end.

units mm
thickness 3 mm

param pitch = 18 mm, min = 14 mm, max = 20 mm
sizes = [2, 2.5, 3, 4, 5, 6]
labels = ["2", "2.5", "3", "4", "5", "6"]

solid holder {
    body = RoundedRectangle(center=(0, 0), width=130, height=40, corner_radius=4)

    hole keys {
        for i in range(len(sizes)) {
            hx = RegularPolygon(center=((i - 2.5) * pitch, 5), across_flats=sizes[i] * 1 mm + 0.2 mm, sides=6)
        }
    }

    hole mount {
        left = Circle(center=(-58, 0), diameter=4)
        right = Circle(center=(58, 0), diameter=4)
    }

    drawing sizes_label {
        for i in range(len(sizes)) {
            t = Text(labels[i], position=((i - 2.5) * pitch, -4), size=4, valign="top")
        }
    }

    assert body.bb.width == 130 mm, "plate 130 mm long"
    assert body.bb.height == 40 mm, "plate 40 mm tall"
    assert len(keys.hx) == 6, "six key holes"
    assert abs(keys.hx[1].center.x - keys.hx[0].center.x - 18 mm) < 0.001 mm, "holes 18 mm apart"
    assert abs(mount.left.center.x - body.bb.left - 7 mm) < 0.001 mm, "mounting hole 7 mm from the end"
    assert abs(sizes_label.t[0].bb.top - (-4 mm)) < 0.01 mm, "labels' top 4 mm below the center line"
}
