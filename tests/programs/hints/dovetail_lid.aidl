// Issue 109 (law 4): a puzzle-box lid, a dovetail socket along each short edge, a finger
// notch and an engraved name. W0401 said to drop lines 26 and 27, "the template holds it
// already"; done as told, the right dovetail moved into the middle of the lid (79 mm),
// through the notch and the engraving. The template's Fixed(self) is where it starts: the
// Align constraints place it, and nothing here is redundant.
import "std/joints.aidl"

units mm
thickness 3 mm

param lid_w = 160
param lid_h = 100

solid lid {
    panel = Rectangle(center=(0, 0), width=lid_w, height=lid_h)
    hole notch { c = Circle(center=(0, 50), radius=10) }
    drawing label { t = Text("PUZZLE", center=(0, 0), size=10) }
    left_tail = dovetail(part="socket", length=60 mm, depth=10 mm, tails=2, rotation=-90 deg)
    right_tail = dovetail(part="socket", length=60 mm, depth=10 mm, tails=2, rotation=90 deg)
    notch.c.center == panel.top.midpoint
    CenterInside(label, panel)
    AlignLeft(left_tail, panel)
    AlignCenterY(left_tail, panel)
    // the right dovetail: placed here, not where the template starts it (at the
    // lid's centre line)
    AlignRight(right_tail, panel)
    AlignCenterY(right_tail, panel)
}
