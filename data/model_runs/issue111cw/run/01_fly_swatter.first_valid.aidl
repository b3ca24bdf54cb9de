# Request (home): a fly swatter cut from 2 mm polypropylene sheet. Head 110 mm wide x 95 mm
# tall with 15 mm corner radii, perforated with a grid of 4 mm holes at 7 mm pitch that keeps a
# solid border of at least 8 mm all round. A 250 mm handle, 18 mm wide, rounded at the end,
# joins the head through a 25 mm neck that widens to 40 mm; an 8 mm hanging hole 12 mm from the
# handle's end; "SPLAT!" engraved along the handle.

units mm
thickness 2 mm

param head_w = 110 mm, min = 80, max = 150
param head_h = 95 mm, min = 70, max = 130
param pitch = 7 mm, min = 6, max = 10
hole_d = 4 mm
border = 8 mm
handle_l = 250 mm
handle_w = 18 mm
neck_h = 25 mm
neck_w = 40 mm

cols = floor((head_w - 2 * border - hole_d) / pitch) + 1
rows = floor((head_h - 2 * border - hole_d) / pitch) + 1
span_x = (cols - 1) * pitch
span_y = (rows - 1) * pitch

solid swatter {
    head = RoundedRectangle(center=(0, 0), width=head_w, height=head_h, corner_radius=15)
    neck = Trapezoid(center=(0, -head_h / 2 - neck_h / 2), bottom_width=handle_w,
                     top_width=neck_w, height=neck_h)
    grip = RoundedRectangle(center=(0, -head_h / 2 - handle_l / 2), width=handle_w,
                            height=handle_l, corner_radii=[0, 0, handle_w / 2, handle_w / 2])

    hole perf {
        c = Circle(center=(-span_x / 2, -span_y / 2), diameter=hole_d)
    }
    grid = GridPattern(perf, rows, cols, (pitch, pitch))

    hole hang {
        eye = Circle(center=(0, -head_h / 2 - handle_l + 12), diameter=8)
    }

    drawing label {
        t = Text("SPLAT!", position=(0, -head_h / 2 - 150), size=8, rotation=90,
                 valign="middle")
    }

    Fillet(5)

    assert head.bb.width == 110 mm, "head 110 mm wide"
    assert head.bb.height == 95 mm, "head 95 mm tall"
    assert head.bb.bottom - grip.bb.bottom == 250 mm, "handle 250 mm below the head"
    assert len(grid) == rows * cols, "one hole per grid place"
    assert grid[0].bb.left - head.bb.left >= 8 mm, "border at least 8 mm (left)"
    assert head.bb.right - grid[rows * cols - 1].bb.right >= 8 mm, "border at least 8 mm (right)"
    assert grid[0].bb.bottom - head.bb.bottom >= 8 mm, "border at least 8 mm (bottom)"
    assert head.bb.top - grid[rows * cols - 1].bb.top >= 8 mm, "border at least 8 mm (top)"
    assert hang.eye.center.y - grip.bb.bottom == 12 mm, "hanging hole 12 mm from the end"
}
