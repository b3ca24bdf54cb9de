# Bathroom: the front panel of a wall cotton-pad dispenser, 3 mm clear acrylic, 90 x 110 mm
# with R6 corners. A 62 mm round window to see the pads, its top 12 mm below the top edge;
# a pull slot at the bottom 64 x 10 mm with round ends, its lower edge 8 mm above the bottom
# edge; four 3.5 mm screw holes 7 mm in from each side, countersunk 7 mm; "COTTON PADS" in
# bold sans, 7 mm tall, engraved filled, centred between the window and the slot.

thickness 3 mm

param w = 90 mm, min = 70 mm, max = 140 mm
param h = 110 mm, min = 90 mm, max = 160 mm
param window_d = 62 mm, min = 40 mm, max = 80 mm

solid front {
    panel = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=6 mm)
    Fixed(panel)

    hole window {
        c = Circle(center=(0, 0), diameter=window_d)
    }
    AlignCenterX(window, panel)
    window.bb.top == panel.bb.top - 12 mm

    hole pull {
        s = Slot(center=(0, -40), length=64 mm, width=10 mm)
    }
    AlignCenterX(pull, panel)
    pull.bb.bottom == panel.bb.bottom + 8 mm

    hole screw {
        c = Circle(center=(-38, -48), diameter=3.5 mm)
    }
    screws = CornerPattern(screw, panel, inset=7 mm)
    Countersink(screws, diameter=7 mm)

    drawing label {
        t = Text("COTTON PADS", position=(0, -28), size=7 mm, font="sans:Bold",
                 valign="middle", fill=true)
    }
    AlignCenterX(label, panel)
    label.t.position.y == (window.bb.bottom + pull.bb.top) / 2

    assert panel.bb.width == 90 mm and panel.bb.height == 110 mm, "90 x 110"
    assert window.c.diameter == 62 mm, "62 mm window"
    assert panel.bb.top - window.bb.top == 12 mm, "window 12 mm below the top"
    assert pull.s.length == 64 mm and pull.s.width == 10 mm, "pull slot 64 x 10"
    assert pull.bb.bottom - panel.bb.bottom == 8 mm, "slot 8 mm above the bottom"
    assert len(screws) == 4, "four screws"
    assert screws[2].c.center.x == panel.bb.right - 7 mm, "7 mm in"
    assert screws[2].c.center.y == panel.bb.top - 7 mm, "7 mm in"
    assert label.t.size == 7 mm, "7 mm letters"
}
