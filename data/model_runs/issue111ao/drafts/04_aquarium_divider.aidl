# Request (pets): a tank divider to keep a betta apart from the other fish in a
# 60 cm tank, cut from 3 mm clear acrylic. A panel 288 mm wide and 300 mm tall
# with R4 corners, perforated for water flow with a honeycomb of 6 mm holes:
# 12 mm apart along a row, rows 10.4 mm apart, every other row shifted half a
# pitch; 21 holes in each row and 23 rows; the field centred left to right and
# its lowest holes 15 mm above the bottom edge. A lifting slot 60 x 16 mm
# (round ends) centred across the top, its top 12 mm below the top edge.
# "BETTA" engraved centred between the field and the lifting slot, 8 mm letters.

thickness 3 mm

panel_w = 288 mm
panel_h = 300 mm
hole_d = 6 mm
col_pitch = 12 mm
row_pitch = 10.4 mm
cols = 21
rows = 23

solid divider {
    body = RoundedRectangle(center=(0, 0), width=panel_w, height=panel_h, corner_radius=4 mm)

    hole perf {
        c = Circle(center=(-120, -130), diameter=hole_d)
    }
    field = GridPattern(perf, rows, cols, col_pitch, row_pitch, stagger=true)
    # the field's lowest holes 15 mm above the bottom edge
    perf.c.bb.bottom == body.bb.bottom + 15 mm
    # centred left to right: the odd rows stick out half a pitch to the right
    perf.c.center.x == body.center.x - (cols - 1) * col_pitch / 2 - col_pitch / 4

    hole lift {
        s = Slot(center=(0, 130), length=60 mm, width=16 mm)
    }
    AlignCenterX(lift, body)
    lift.bb.top == body.bb.top - 12 mm

    drawing label {
        word = Text("BETTA", position=(0, 110), size=8, valign="middle")
    }
    AlignCenterX(label, body)
    label.bb.center_y == (field[len(field) - 1].c.bb.top + lift.bb.bottom) / 2

    assert body.bb.width == 288 mm and body.bb.height == 300 mm, "panel 288 x 300"
    assert len(field) == 21 * 23, "21 holes a row, 23 rows"
    assert field[0].c.diameter == 6 mm, "6 mm holes"
    assert field[1].c.center.x - field[0].c.center.x == 12 mm, "12 mm along a row"
    assert field[21].c.center.y - field[0].c.center.y == 10.4 mm, "rows 10.4 mm apart"
    assert field[21].c.center.x - field[0].c.center.x == 6 mm, "odd rows shifted half a pitch"
    assert abs((field[0].c.bb.left - body.bb.left) - (body.bb.right - field[21 + 20].c.bb.right)) < 0.001 mm,
        "field centred left to right"
    assert field[0].c.bb.bottom - body.bb.bottom == 15 mm, "lowest holes 15 mm up"
    assert lift.s.length == 60 mm and lift.s.width == 16 mm, "lifting slot 60 x 16"
    assert body.bb.top - lift.bb.top == 12 mm, "slot 12 mm below the top"
}
