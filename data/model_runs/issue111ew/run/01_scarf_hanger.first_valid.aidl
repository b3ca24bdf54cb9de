# Request (home): a scarf organiser that hangs from the wardrobe rail. 6 mm birch ply,
# one piece. Board 300 mm wide x 340 mm tall with R15 corners. 16 round holes of 50 mm
# for the scarves, a 4 x 4 grid on 70 mm centres, centred across the board, with at least
# 20 mm of wood between the holes and the board's edges. A hook off the top centre, a
# band 14 mm wide, that hooks over a rail up to 32 mm across (32 mm opening), its top
# 70 mm above the board. "SCARVES" engraved (filled bold letters, 14 mm high) across the
# top strip above the holes, at least 5 mm clear of them. The corners where the hook
# meets the board rounded R6.

units mm
thickness 6 mm

solid scarf_hanger {
    body = RoundedRectangle(center=(0, 0), width=300, height=340, corner_radius=15)

    # hook: neck up from inside the board, a half turn over to the left, a short tip down
    neck = Line((0, 160), (0, 210))
    bend = Arc(center=(-23, 210), radius=23, start_angle=0 deg, end_angle=180 deg)
    tip = Line((-46, 210), (-46, 198))
    hook = Stroke([neck, bend, tip], width=14)

    hole ring {
        c = Circle(center=(-105, -125), diameter=50)
    }
    rings = GridPattern(ring, 4, 4, 70)

    drawing label {
        t = Text("SCARVES", position=(0, 140), size=14, font="sans:Bold", valign="middle",
                 fill=true)
    }

    Fillet(6)

    assert len(rings) == 16, "16 holes"
    assert rings[0].c.diameter == 50 mm
    assert distance(rings[0].c.center, rings[1].c.center) == 70 mm, "70 mm centres across"
    assert distance(rings[0].c.center, rings[4].c.center) == 70 mm, "70 mm centres up"
    assert rings[0].bb.left - body.bb.left >= 20 mm, "20 mm wood at the left"
    assert body.bb.right - rings[15].bb.right >= 20 mm, "20 mm wood at the right"
    assert rings[0].bb.bottom - body.bb.bottom >= 20 mm, "20 mm wood at the bottom"
    assert abs((rings[0].bb.left + rings[15].bb.right) / 2 - body.bb.center_x) < 0.01 mm,
        "grid centred across"
    assert distance(neck, tip) - 14 mm == 32 mm, "32 mm rail opening"
    assert hook.bb.top - body.bb.top == 70 mm, "hook top 70 mm above the board"
    assert distance(label, rings) >= 5 mm, "label clear of the holes"
    assert label.bb.top <= body.bb.top - 5 mm, "label on the board"
}
