# Request: a wine-cork keeper for the kitchen shelf. A finger-jointed box of 3 mm ply,
# 150 mm wide x 100 mm deep x 200 mm tall outside (10 mm fingers), closed. Corks go in
# through a 26 mm round hole in the middle of the lid (corks are 24 mm across); the lid is
# left unglued so it lifts off to empty the box. The front has a window 100 x 130 mm with
# 8 mm round corners, centred left-right, its bottom 30 mm above the box's bottom edge, and
# behind it a 3 mm clear acrylic pane 110 x 140 mm (cut from the same job) glued to the
# inside of the front. Above the window "CORKS" in bold letters 14 mm tall, engraved filled,
# its baseline 12 mm above the window.

import "std/joints.aidl"

thickness 3 mm

param box_w = 150 mm, min = 100 mm, max = 250 mm
param box_d = 100 mm, min = 70 mm, max = 200 mm
param box_h = 200 mm, min = 150 mm, max = 300 mm
win_w = 100 mm
win_h = 130 mm
win_up = 30 mm
pane_w = 110 mm
pane_h = 140 mm
cork_hole = 26 mm

assembly cork_keeper {
    box = finger_box(length=box_w, depth=box_d, height=box_h, thickness=3 mm, finger=10 mm)

    # the cork hole in the middle of the lid
    hole mouth { c = Circle(center=(0, 0), diameter=cork_hole) }
    CenterInside(mouth, box.lid)
    CutInto(mouth, box.lid)

    # the window in the front
    hole window {
        w = RoundedRectangle(center=(0, 0), width=win_w, height=win_h, corner_radius=8)
    }
    AlignCenterX(window, box.front)
    window.bb.bottom == box.front.bb.bottom + win_up
    CutInto(window, box.front)

    # the engraved word above the window
    drawing word {
        t = Text("CORKS", position=(0, 0), size=14, font="sans:Bold", fill=true)
    }
    AlignCenterX(word.t.position, box.front)
    word.t.position.y == window.bb.top + 12
    CutInto(word, box.front)

    # the acrylic pane, laid beside the box on the sheet, glued behind the window
    solid pane {
        p = RoundedRectangle(center=(0, 0), width=pane_w, height=pane_h, corner_radius=3)
    }
    RightOf(pane, box, gap=10)
    AlignBottom(pane, box)
    # assembled: against the inside of the front, centred on the window
    Place(pane, position=(0, -box_d / 2 + 6, win_up + win_h / 2), face="front", up="up")

    # the request's numbers
    assert box.front.bb.width == 150 mm, "box 150 wide outside"
    assert box.front.bb.height == 200 mm, "box 200 tall outside"
    assert box.left.bb.height == 100 mm, "box 100 deep outside"
    assert mouth.c.diameter == 26 mm, "cork hole 26 mm"
    assert window.bb.width == 100 mm and window.bb.height == 130 mm, "window 100 x 130"
    assert window.bb.bottom - box.front.bb.bottom == 30 mm, "window 30 up"
    assert word.t.position.y - window.bb.top == 12 mm, "word baseline 12 above window"
    assert pane.bb.width - window.bb.width == 10 mm, "pane overlaps the window 5 mm each side"
    assert word.bb.top < box.front.bb.top - 3 mm, "word clear of the lid's fingers"
}
