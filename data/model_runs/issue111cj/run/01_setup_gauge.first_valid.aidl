# Request: a router / table-saw set-up gauge cut from 6 mm clear acrylic. A strip 160 mm long
# whose bottom edge stands on the table; its top edge is a staircase of six steps, each 20 mm
# wide, at 6, 9, 12, 15, 18 and 25 mm above the bottom edge, the height engraved on each step.
# At the left end a 40 mm wide, 35 mm tall handle with its top corners rounded r 8, an 8 mm
# hanging hole centred in it 9 mm below its top, and "SET-UP" engraved under the hole.

units mm
thickness 6 mm

heights = [6, 9, 12, 15, 18, 25]
step_w = 20 mm
handle_w = 40 mm
handle_h = 35 mm

solid gauge {
    handle = RoundedRectangle(bottom_left=(0, 0), width=handle_w, height=handle_h,
                              corner_radii=[8, 8, 0, 0])
    for i in range(len(heights)) {
        step = Rectangle(bottom_left=(handle_w + i * step_w, 0), width=step_w, height=heights[i])
    }
    hole hang {
        c = Circle(center=(handle_w / 2, handle_h - 9), diameter=8)
    }
    drawing marks {
        for i in range(len(heights)) {
            t = Text(str(heights[i]), position=(handle_w + (i + 0.5) * step_w, heights[i] / 2),
                     size=min(4, heights[i] - 2), valign="middle")
        }
        name = Text("SET-UP", position=(handle_w / 2, 11), size=5, valign="middle")
    }
    Fixed(handle)

    assert len(step) == 6, "six steps"
    assert step[0].bb.top - handle.bb.bottom == 6 mm
    assert step[1].bb.top - handle.bb.bottom == 9 mm
    assert step[2].bb.top - handle.bb.bottom == 12 mm
    assert step[3].bb.top - handle.bb.bottom == 15 mm
    assert step[4].bb.top - handle.bb.bottom == 18 mm
    assert step[5].bb.top - handle.bb.bottom == 25 mm
    assert step[5].bb.right - handle.bb.left == 160 mm, "160 mm long"
    assert handle.bb.top - hang.c.center.y == 9 mm
    assert hang.c.diameter == 8 mm
}
