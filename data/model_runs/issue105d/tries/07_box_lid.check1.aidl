# Box lid for a 100 x 60 mm (outer) box of 3 mm sheet: a 100 x 60 mm panel with finger
# joints (10 mm fingers) on all four edges, and a 30 x 10 mm finger-pull slot in its centre.
import "std/joints.aidl"
param length = 100 mm, min = 60 mm, max = 200 mm
param width = 60 mm, min = 40 mm, max = 150 mm
thickness 3 mm

solid lid {
    panel = finger_panel(width=length, height=width, thickness=3 mm, finger=10 mm)
    hole pull {
        s = Slot(center=(0, 0), length=30, width=10)
    }
    CenterInside(pull, panel.outline)
    assert panel.outline.width == 100 mm and panel.outline.height == 60 mm, "lid 100 x 60 mm"
}
