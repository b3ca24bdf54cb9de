# Electronics: light grid (diffuser baffle) for an 8 x 8 LED matrix at 10 mm pitch, 3 mm black
# acrylic. Plate 100 x 100 mm, corners R3. 64 square cells 8.4 mm wide (cell corners R0.5),
# 10 mm apart, the grid centred on the plate. Four M3 holes (3.2 mm) 5 mm in from each corner.
# A small engraved "IN" 3 mm tall under the bottom-left cell marks the data-in corner.

thickness 3 mm
param pitch = 10 mm, min = 8 mm, max = 12 mm
param cell = 8.4 mm, min = 6 mm, max = 9.4 mm
param n = 8, min = 4, max = 8

solid grid {
    body = RoundedRectangle(center=(0, 0), width=100, height=100, corner_radius=3)

    hole window {
        w = RoundedRectangle(center=(-35, -35), width=cell, height=cell, corner_radius=0.5)
    }
    cells = GridPattern(window, n, n, pitch)
    # the grid's middle is the plate's centre
    window.w.center.x == body.center.x - (n - 1) * pitch / 2
    window.w.center.y == body.center.y - (n - 1) * pitch / 2

    hole screw {
        c = Circle(center=(-45, -45), diameter=3.2)
    }
    CornerPattern(screw, body, inset=5)

    drawing mark {
        t = Text("IN", (-35, -44), size=3)
    }
    AlignCenterX(mark, window)
    mark.bb.top == window.bb.bottom - 1

    assert body.bb.width == 100 mm and body.bb.height == 100 mm, "plate 100 x 100"
    assert len(cells) == 64, "64 cells"
    assert cells[1].w.center.x - cells[0].w.center.x == 10 mm, "10 mm pitch"
    assert abs(window.w.bb.width - 8.4 mm) < 0.001, "cells 8.4 wide"
    assert abs((cells[0].w.center.x + cells[63].w.center.x) / 2 - body.center.x) < 0.01, "grid centred in x"
    assert abs((cells[0].w.center.y + cells[63].w.center.y) / 2 - body.center.y) < 0.01, "grid centred in y"
    assert screw.c.center.x - body.bb.left == 5 mm and screw.c.center.y - body.bb.bottom == 5 mm, "screw 5 in"
}
