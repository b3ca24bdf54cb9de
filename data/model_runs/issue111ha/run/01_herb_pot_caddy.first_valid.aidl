# Request (kitchen): "A windowsill caddy for three supermarket herb pots. The pots are 90 mm
# across the rim and taper to 75 mm, so they should drop through 84 mm holes and hang by the rim.
# Make it a finger-jointed box 320 mm long, 110 mm deep and 100 mm tall (outside), from 4 mm
# birch ply, three 84 mm holes in a row in the top plate, and engrave the herb names BASIL,
# PARSLEY and CHIVES in 12 mm bold capitals on the front panel, each under its pot."

import "std/stands.aidl"

thickness 4 mm

param length = 320 mm, min = 270 mm, max = 400 mm
param depth = 110 mm, min = 95 mm, max = 150 mm
param height = 100 mm, min = 80 mm, max = 140 mm
param pot_hole = 84 mm, min = 70 mm, max = 88 mm

names = ["BASIL", "PARSLEY", "CHIVES"]
# the top plate is drilled inside its joints: 3 holes spread over length - 2 * 4 mm
pitch = (length - 8 mm) / 3

assembly herb_caddy {
    caddy = tool_holder(length=length, depth=depth, height=height, thickness=4 mm,
                        finger=12 mm, rows=1, cols=3, hole=pot_hole)

    drawing labels {
        for i in range(3) {
            t = Text(names[i], position=((i - 1) * pitch, 0), size=12, valign="middle",
                     font="sans:Bold", fill=true)
        }
    }
    # the middle name sits under the middle pot, the row in the panel's middle height
    AlignCenterX(labels.t[1], caddy.front)
    AlignCenterY(labels, caddy.front)
    CutInto(labels, caddy.front)

    assert caddy.length == 320 mm, "320 mm long"
    assert caddy.depth == 110 mm, "110 mm deep"
    assert caddy.height == 100 mm, "100 mm tall"
    assert caddy.hole == 84 mm, "84 mm pot holes"
    assert len(labels.t) == 3, "three herb names"
    assert labels.bb.width <= caddy.front.bb.width - 16 mm, "names stay on the front panel"
}
