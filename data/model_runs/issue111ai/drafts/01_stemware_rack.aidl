# Request (kitchen): an under-cabinet wine-glass rack for 4 glasses, cut from 6 mm birch ply.
# A plate 300 mm wide (along the cabinet front) x 200 mm deep, its two front corners rounded
# R10. Four slots open at the front edge, 16 mm wide (stems up to 12 mm), 150 mm deep from the
# front edge, at a 75 mm pitch centred on the plate; each mouth flares to 28 mm wide over its
# first 10 mm so a stem finds its way in. Six 4.5 mm screw holes countersunk for 9 mm heads:
# two in each of the three inner tongues, 40 mm and 120 mm from the front edge. "CHEERS"
# engraved 10 mm high, centred in the 50 mm strip behind the slots. Every other corner
# softened with a 2 mm fillet so nothing scratches a glass.

units mm
thickness 6 mm

plate_w = 300 mm
plate_d = 200 mm
slot_w = 16 mm
slot_depth = 150 mm
pitch = 75 mm
flare_w = 28 mm
flare_len = 10 mm

solid rack {
    # the front edge is the bottom edge of the drawing (y = 0), the back edge at y = 200
    body = RoundedRectangle(bottom_left=(-plate_w / 2, 0), width=plate_w, height=plate_d,
                            corner_radii=[0, 0, 10, 10])

    hole slots {
        for i in range(4) {
            # runs from 8 mm below the front edge (so it opens cleanly) to 150 mm in
            s = Slot(center=((i - 1.5) * pitch, (slot_depth - slot_w / 2) / 2),
                     length=slot_depth + slot_w / 2, width=slot_w, rotation=90, overrun=true)
            mouth = Polygon([((i - 1.5) * pitch - flare_w / 2, -1), ((i - 1.5) * pitch + flare_w / 2, -1),
                             ((i - 1.5) * pitch + slot_w / 2, flare_len),
                             ((i - 1.5) * pitch - slot_w / 2, flare_len)], overrun=true)
        }
    }

    hole screw {
        c = Circle(center=(-pitch, 40), diameter=4.5)
    }
    screws = GridPattern(screw, 2, 3, (pitch, 80))
    Countersink(screws, diameter=9)

    drawing label {
        word = Text("CHEERS", (0, slot_depth + (plate_d - slot_depth) / 2), size=10,
                    valign="middle")
    }

    Fillet(2)

    assert len(slots.s) == 4, "four glasses"
    assert body.bb.width == 300 mm and body.bb.height == 200 mm, "plate 300 x 200"
    assert slots.s[0].width == 16 mm, "16 mm slots"
    assert slots.s[0].bb.top - body.bb.bottom == 150 mm, "slots 150 mm deep from the front"
    assert slots.s[1].center.x - slots.s[0].center.x == 75 mm, "75 mm pitch"
    assert len(screws) == 6, "six screws"
    assert screws[0].c.center.y - body.bb.bottom == 40 mm, "first row 40 mm from the front"
    assert screws[3].c.center.y - body.bb.bottom == 120 mm, "second row 120 mm from the front"
}
