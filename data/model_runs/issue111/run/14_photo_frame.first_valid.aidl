# Photo-frame front for a 100 x 150 mm (4 x 6 in) photo, portrait: 140 x 190 mm outer with
# 8 mm rounded corners, a 98 x 148 mm window (1 mm overlap on the photo each side)
# centered; a keyhole (8 mm head, 4 mm slot, 6 mm long, upward) centered across, its head's
# center 7 mm above the window's top edge.

import "std/plates.aidl"

solid frame {
    body = RoundedRectangle(center=(0, 0), width=140, height=190, corner_radius=8)
    hole window {
        w = Rectangle(center=(0, 0), width=98, height=148)
    }
    CenterInside(window, body)
    hang = keyhole(head=8 mm, slot_width=4 mm, length=6 mm, direction=90 deg, cx=0 mm, cy=81 mm)
    AlignCenterX(hang.head_hole, body)
    hang.head_hole.center.y == window.bb.top + 7 mm
    assert body.bb.width == 140 mm and body.bb.height == 190 mm, "140 x 190 outer"
    assert window.w.width == 98 mm and window.w.height == 148 mm, "98 x 148 window"
    assert body.bb.top - hang.bb.top >= 4 mm, "keyhole slot well inside the top border"
}
