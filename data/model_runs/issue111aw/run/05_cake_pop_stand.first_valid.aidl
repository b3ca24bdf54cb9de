# Request (parties): a cake-pop stand for a birthday table, 3 mm ply. A finger-jointed box
# 240 mm long, 90 mm deep and 60 mm tall (outside) whose top plate has 2 rows of 8 holes,
# 5 mm across, for the lollipop sticks. "CAKE POPS" engraved as filled bold letters 14 mm tall
# in the middle of the front panel; "HAPPY 7TH BIRTHDAY LILY" engraved 6 mm tall on the back
# panel, so it reads from the other side of the table. Show it assembled.

import "std/stands.aidl"

units mm
thickness 3 mm

assembly stand {
    pops = tool_holder(length=240 mm, depth=90 mm, height=60 mm, thickness=3 mm, finger=10 mm,
                       rows=2, cols=8, hole=5 mm, outside=true)

    drawing front_label {
        t = Text("CAKE POPS", position=(0, 0), size=14, font="sans:Bold", valign="middle",
                 fill=true)
    }
    CenterInside(front_label, pops.front)
    CutInto(front_label, pops.front)

    drawing back_label {
        t = Text("HAPPY 7TH BIRTHDAY LILY", position=(0, 0), size=6, valign="middle")
    }
    CenterInside(back_label, pops.back)
    CutInto(back_label, pops.back)

    # the request's own numbers
    assert pops.length == 240 mm and pops.depth == 90 mm and pops.height == 60 mm,
        "box 240 x 90 x 60"
    assert pops.rows * pops.cols == 16, "2 rows of 8 holes"
    assert pops.hole == 5 mm, "5 mm holes"
    assert front_label.bb.width < pops.front.bb.width - 30, "front label well inside the panel"
    assert back_label.bb.width < pops.back.bb.width - 30, "back label well inside the panel"
}
