# Request: a wrap-around cover for an A5 notebook (148 x 210 x 12 mm), cut in one piece from
# 3 mm birch ply. Front and back panels 154 x 216 mm each, joined by a living-hinge spine
# that bends round the notebook in two 90 degree bends of 7 mm inside radius (a 14 mm
# spine gap); outer corners R6. Each panel has two elastic slots 20 x 3 mm across its two
# outer corners (centred 20 mm in from both edges) to hold the notebook's card covers.
# The back has two 4 mm holes for a closing elastic, 12 mm from its outer edge and 8 mm
# from top and bottom. The front has an engraved frame 8 mm in from its edges (R4) and
# "SKETCHES" engraved filled, 12 mm tall, centred 40 mm above the middle; the back
# has "A5 / 2026" engraved small near its bottom.

import "std/plates.aidl"

thickness 3 mm

PANEL_W = 154 mm
PANEL_H = 216 mm
BEND_R = 7 mm
# each 90 deg bend is 90 deg x (radius + half the thickness) wide on the sheet
SPINE = 2 * (pi / 2) * (BEND_R + 1.5 mm)

def corner_slot(x, y, r) -> hole {
    s = Slot(center=(x, y), length=20, width=3, rotation=r)
}

assembly notebook {
    solid cover {
        body = RoundedRectangle(center=(0, 0), width=2 * PANEL_W + SPINE, height=PANEL_H,
                                corner_radius=6)
        spine = living_hinge(width=SPINE, height=PANEL_H, cx=0, cy=0)

        # front panel: right of the spine; back panel: left of it
        fx = SPINE / 2 + PANEL_W / 2
        bx = -fx
        fr_top = corner_slot(fx + PANEL_W / 2 - 20, PANEL_H / 2 - 20, -45 deg)
        fr_bot = corner_slot(fx + PANEL_W / 2 - 20, -PANEL_H / 2 + 20, 45 deg)
        bk_top = corner_slot(bx - PANEL_W / 2 + 20, PANEL_H / 2 - 20, 45 deg)
        bk_bot = corner_slot(bx - PANEL_W / 2 + 20, -PANEL_H / 2 + 20, -45 deg)

        hole closure {
            top = Circle(center=(bx - PANEL_W / 2 + 12, PANEL_H / 2 - 8), diameter=4)
            bottom = Circle(center=(bx - PANEL_W / 2 + 12, -PANEL_H / 2 + 8), diameter=4)
        }

        drawing front_art {
            frame = RoundedRectangle(center=(fx, 0), width=PANEL_W - 16, height=PANEL_H - 16,
                                     corner_radius=4)
            title = Text("SKETCHES", position=(fx, 40), size=12, font="sans:Bold",
                         valign="middle", fill=true)
        }
        drawing back_mark {
            t = Text("A5 / 2026", position=(bx, -PANEL_H / 2 + 14), size=4, valign="middle")
        }
    }

    # assembled: outside face up, the spine wrapped round in two bends; the front ends up
    # underneath, 14 mm below the back
    Place(cover, position=(0, 0, 0), face="up")
    Bend(cover, at=-SPINE / 4, angle=-90 deg, radius=BEND_R)
    Bend(cover, at=SPINE / 4, angle=-90 deg, radius=BEND_R)

    assert cover.body.width == 2 * 154 mm + SPINE, "two 154 mm panels and the spine"
    assert cover.body.height == 216 mm, "216 tall"
    assert 2 * BEND_R == 14 mm, "14 mm spine gap for a 12 mm notebook"
    assert cover.spine.bb.width <= SPINE, "the hinge stays in the spine"
    assert cover.front_art.frame.bb.right - cover.body.bb.right == -8 mm, "frame 8 in"
    assert cover.front_art.frame.bb.left - cover.spine.bb.right >= 8 mm, "frame clear of the hinge"
    assert cover.closure.top.center.x - cover.body.bb.left == 12 mm, "closure 12 from the edge"
    assert cover.body.bb.top - cover.closure.top.center.y == 8 mm, "closure 8 from the top"
    assert distance(cover.front_art.title, cover.fr_top) >= 5 mm, "title clear of the slots"
}
