# Request: a macaron piping template in 1.5 mm clear acrylic, slid under the baking paper on a
# half-sheet tray and pulled out before baking. Sheet 300 x 200 mm, corners R8. 24 shells in
# 4 staggered rows of 6: each an engraved 38 mm circle with a filled 3 mm dot at its centre;
# 42 mm between centres along a row, 38 mm between rows, every second row shifted half a pitch
# (21 mm) to the right; the top row's circles 10 mm below the top edge, the block of circles
# centred left to right. Under them "MACARONS 38 mm" engraved filled in a bold sans, 10 mm
# capitals, centred in the strip below the circles. A 6 mm hanging hole centred 10 mm from the
# top and left edges, and a R12 thumb notch on the right edge, centred on the label's line.
# Every circle at least 8 mm from the sheet's edge and from the hanging hole.

thickness 1.5 mm

param rows = 4, min = 2, max = 4
param cols = 6, min = 3, max = 6
pitch = 42 mm
row_pitch = 38 mm
shell_d = 38 mm

solid template {
    sheet = RoundedRectangle(center=(0, 0), width=300, height=200, corner_radius=8)
    Fixed(sheet)

    drawing shell {
        ring = Circle(center=(-150 + (300 - ((cols - 1) * pitch + pitch / 2 + shell_d)) / 2 + shell_d / 2,
                              100 - 10 - shell_d / 2), diameter=shell_d)
        dot = Circle(center=ring.center, diameter=3, fill=true)
    }
    shells = GridPattern(shell, rows, cols, (pitch, -row_pitch), stagger=true)

    drawing label {
        t = Text("MACARONS 38 mm", position=(0, -81), size=10, font="sans:Bold",
                 valign="middle", fill=true)
    }

    hole hang { c = Circle(center=(-140, 90), diameter=6) }
    hole thumb { c = Circle(center=(150, -81), radius=12) }

    # the request's numbers
    assert len(shells) == 24, "24 shells"
    assert shell.ring.diameter == 38 mm, "38 mm circles"
    assert shells[1].ring.center.x - shells[0].ring.center.x == 42 mm, "42 mm along a row"
    assert shells[0].ring.center.y - shells[cols].ring.center.y == 38 mm, "38 mm between rows"
    assert shells[cols].ring.center.x - shells[0].ring.center.x == 21 mm, "odd rows shifted 21"
    assert sheet.bb.top - shell.ring.bb.top == 10 mm, "top row 10 below the top edge"
    assert abs((min([s.bb.left for s in shells]) - sheet.bb.left) -
               (sheet.bb.right - max([s.bb.right for s in shells]))) < 0.01 mm, "block centred"
    assert min([s.bb.left for s in shells]) - sheet.bb.left >= 8 mm, "8 mm to the left edge"
    assert sheet.bb.right - max([s.bb.right for s in shells]) >= 8 mm, "8 mm to the right edge"
    assert distance(hang.c, shells) >= 8 mm, "8 mm from the hanging hole"
    assert sheet.bb.top - hang.c.center.y == 10 mm and hang.c.center.x - sheet.bb.left == 10 mm,
        "hanging hole 10 from top and left"
    assert thumb.c.center.x == sheet.bb.right and thumb.c.center.y == label.t.position.y,
        "thumb notch on the right edge, on the label's line"
    assert min([s.bb.bottom for s in shells]) - label.bb.top >= 5 mm, "label clear of the circles"
    assert label.bb.bottom - sheet.bb.bottom >= 8 mm, "label inside the sheet"
    assert distance(label, thumb) >= 5 mm, "label clear of the notch"
}
