# Request (office): a two-drawer desk unit for 76 mm sticky-note pads and paper clips, 3 mm
# ply. Two drawer units, each 100 mm wide x 100 mm deep x 50 mm tall outside, glued one on
# top of the other. Each drawer has the usual round finger pull in its front; above the pull
# the front is engraved with what it holds, 6 mm tall: "NOTES" (upper drawer) and "CLIPS"
# (lower drawer). A 76 x 76 mm pad must lie flat inside a drawer.
units mm
thickness 3 mm
import "std/boxes.aidl"

param w = 100 mm, min = 90, max = 200
param d = 100 mm, min = 90, max = 200
param h = 50 mm, min = 40, max = 100

assembly note_drawers {
    upper = drawer(length=w, depth=d, height=h, thickness=3 mm, finger=10 mm)
    lower = drawer(length=w, depth=d, height=h, thickness=3 mm, finger=10 mm)
    Below(lower, upper, gap=10 mm)
    AlignCenterX(lower, upper)

    drawing notes {
        t = Text("NOTES", position=(0, 0), size=6, valign="middle")
    }
    AlignCenterX(notes, upper.box.front)
    notes.t.position.y == upper.box.front.bb.top - 9 mm
    CutInto(notes, upper.box.front)

    drawing clips {
        t = Text("CLIPS", position=(0, 0), size=6, valign="middle")
    }
    AlignCenterX(clips, lower.box.front)
    clips.t.position.y == lower.box.front.bb.top - 9 mm
    CutInto(clips, lower.box.front)

    assert upper.length == 100 mm and upper.depth == 100 mm and upper.height == 50 mm,
        "100 x 100 x 50 outside"
    assert min(upper.box.bottom.bb.width, upper.box.bottom.bb.height) - 2 * 3 mm >= 76 mm,
        "a 76 mm pad lies flat in the drawer"
    assert notes.bb.top < upper.box.front.bb.top - 3 mm, "label on the front"
}
