# Request (parties): a chip-and-dip tray for game nights, two layers of 6 mm ply
# glued together, each 400 x 260 mm with 25 mm rounded corners. The top layer is a
# frame: a 220 x 190 mm opening (20 mm corner radius) on the left for the chips, 30 mm
# from the left edge and centred top to bottom, and on the right two 100 mm round
# wells for dip ramekins, one above the other with a 10 mm bridge between them,
# 25 mm in from the right edge. The bottom layer is plain and closes the wells.
# Four 6 mm dowel holes, 18 mm in from both edges at each corner, go through both
# layers to line them up for gluing. GAME DAY is engraved on the frame above the chip
# opening, 12 mm bold letters, filled, centred on the opening and on the strip.

thickness 6 mm

tray_w = 400 mm
tray_h = 260 mm
chip_w = 220 mm
chip_h = 190 mm
well_d = 100 mm
bridge = 10 mm

chip_x = -tray_w / 2 + 30 mm + chip_w / 2
well_x = tray_w / 2 - 25 mm - well_d / 2
well_y = bridge / 2 + well_d / 2

assembly tray {
    solid frame {
        body = RoundedRectangle(center=(0, 0), width=tray_w, height=tray_h, corner_radius=25 mm)
        hole openings {
            chips = RoundedRectangle(center=(chip_x, 0), width=chip_w, height=chip_h,
                                     corner_radius=20 mm)
            dip = Circle(center=(well_x, well_y), diameter=well_d)
            salsa = Circle(center=(well_x, -well_y), diameter=well_d)
        }
        hole dowel { c = Circle(center=(0, 0), diameter=6 mm) }
        dowels = CornerPattern(dowel, body, inset=18 mm)
        drawing words {
            t = Text("GAME DAY", position=(chip_x, (chip_h / 2 + tray_h / 2) / 2), size=12 mm,
                     font="sans:Bold", fill=true, valign="middle")
        }
        Fixed(body)
    }

    solid base {
        body = RoundedRectangle(center=(0, 0), width=tray_w, height=tray_h, corner_radius=25 mm)
        hole dowel { c = Circle(center=(0, 0), diameter=6 mm) }
        dowels = CornerPattern(dowel, body, inset=18 mm)
    }
    Below(base, frame, gap=10 mm)
    AlignLeft(base, frame)

    assert frame.body.bb.width == 400 mm and frame.body.bb.height == 260 mm, "400 x 260"
    assert frame.openings.chips.bb.left - frame.body.bb.left == 30 mm, "chips 30 mm from the left"
    assert frame.body.bb.right - frame.openings.dip.bb.right == 25 mm, "wells 25 mm from the right"
    assert frame.openings.dip.bb.bottom - frame.openings.salsa.bb.top == 10 mm, "10 mm bridge"
    assert frame.openings.dip.diameter == 100 mm, "100 mm wells"
    assert frame.openings.dip.bb.left - frame.openings.chips.bb.right >= 20 mm,
        "a strong web between chips and wells"
    assert distance(frame.words, frame.openings) >= 5 mm, "words clear of the opening"
    assert frame.dowel.c.center.x - frame.body.bb.left == 18 mm, "dowels 18 mm in"
    assert len(frame.dowels) == 4 and len(base.dowels) == 4, "four dowels a layer"
}
