# Tissue-box top panel: 250 x 130 mm outer size, 3 mm sheet, finger joints (10 mm fingers)
# on all four edges; a 150 x 40 mm stadium-shaped opening for the tissues in the center;
# "TISSUES" engraved 8 mm tall centered 20 mm below the opening... no: above it is the
# lid's front; put it 12 mm below the opening's lower edge.

import "std/joints.aidl"

thickness 3 mm

solid top {
    panel = finger_panel(width=250 mm, height=130 mm, thickness=3 mm, finger=10 mm)
    hole opening {
        s = Slot(center=(0, 0), length=150, width=40)
    }
    CenterInside(opening, panel.outline)
    drawing label {
        t = Text("TISSUES", position=(0, -35), size=8, valign="top")
    }
    AlignCenterX(label, panel.outline)
    label.bb.top == opening.bb.bottom - 12 mm
    assert panel.outline.width == 250 mm and panel.outline.height == 130 mm, "250 x 130 outer"
    assert opening.s.length == 150 mm and opening.s.width == 40 mm, "150 x 40 opening"
    assert label.bb.bottom > panel.outline.bottom.midpoint.y + 3 mm + 3 mm, "label clear of the fingers"
}
