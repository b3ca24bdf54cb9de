# Request: a "pocket hugs" gift, cut from 3 mm ply: a finger-jointed box with a sliding lid,
# 100 x 70 x 30 mm outside, its lid engraved "POCKET HUGS" in 7 mm capitals above a filled
# engraved heart 17 mm wide, both centred across the lid and kept clear of the lid's finger
# pull; and four heart-shaped tokens 34 mm wide and 30 mm tall (two 18 mm round lobes 16 mm
# apart, coming to a point) engraved "HUG" in 7 mm capitals, which lie stacked inside the box.

import "std/boxes.aidl"

thickness 3 mm

param box_l = 100 mm, min = 80 mm, max = 160 mm
param box_w = 70 mm, min = 60 mm, max = 120 mm
param box_h = 30 mm, min = 20 mm, max = 60 mm
param tokens = 4, min = 1, max = 6
t = 3 mm

def token() -> solid {
    left_lobe = Hull(Circle(center=(-8, 5), radius=9), Point(0, -16))
    right_lobe = Hull(Circle(center=(8, 5), radius=9), Point(0, -16))
    drawing word {
        w = Text("HUG", position=(0, 3), size=7, valign="middle")
    }
    Rigid(self)
}

assembly hug_box {
    box = sliding_lid_box(length=box_l, width=box_w, height=box_h, thickness=t, finger=10 mm)

    drawing lid_art {
        heart_l = Hull(Circle(center=(-4, 2.5), radius=4.5), Point(0, -8), fill=true)
        heart_r = Hull(Circle(center=(4, 2.5), radius=4.5), Point(0, -8), fill=true)
        words = Text("POCKET HUGS", position=(0, 14), size=7, valign="middle")
        Rigid(self)
    }
    AlignCenterX(lid_art, box.lid)
    lid_art.bb.bottom == box.lid.pull.bb.top + 6 mm
    CutInto(lid_art, box.lid)

    for i in range(tokens) {
        tok = token()
        # stacked flat on the box's floor
        Place(tok, position=(0, 0, t + i * t))
    }

    # on the sheet: the tokens in a row under the box's net
    Below(tok[0], box, gap=10)
    AlignLeft(tok[0], box)
    for i in range(1, tokens) {
        RightOf(tok[i], tok[i - 1], gap=6)
        AlignTop(tok[i], tok[i - 1])
    }

    assert box.front.bb.width <= 100 mm and box.bottom.bb.width <= 100 mm, "100 mm long outside"
    assert len(tok) == 4, "four tokens"
    assert tok[0].bb.width == 34 mm and tok[0].bb.height == 30 mm, "tokens 34 x 30"
    assert lid_art.heart_r.bb.right - lid_art.heart_l.bb.left == 17 mm, "lid heart 17 mm wide"
    assert distance(lid_art, box.lid.pull) >= 3 mm, "engraving clear of the pull"
    assert tok[0].bb.width < box.lid.bb.height - 2 * 3 mm, "a token fits across the box"
    assert 4 * 3 mm < 30 mm - 2 * 3 mm, "the stack fits under the lid"
}
