# Request (kitchen): a biscuit barrel for the worktop, 3 mm birch ply: a rounded box
# 160 x 160 mm outside, 180 mm tall, corners of 40 mm radius, its wall bent round on
# living hinges, with a lift-off lid. On the lid, engraved: BISCUITS in bold serif
# letters 14 mm tall, filled, arching over the knob (baselines on a 45 mm radius
# circle about the lid's centre), and EST. 2026 8 mm tall under the knob, reading the
# right way up. The knob is two glued discs: a 45 mm top disc with eight 4 mm dots
# engraved round it on a 32 mm circle (like a custard cream) and a 28 mm neck disc
# under it, glued to the lid's centre.

import "std/boxes.aidl"

thickness 3 mm

param box_w = 160 mm, min = 100 mm, max = 300 mm
param box_h = 180 mm, min = 80 mm, max = 300 mm
corner = 40 mm
ring_r = 45 mm
knob_d = 45 mm
neck_d = 28 mm

assembly barrel {
    box = flex_box(length=box_w, width=box_w, height=box_h, radius=corner, thickness=3 mm)

    drawing lid_art {
        ring = Circle(center=(0, 0), radius=ring_r, construction=true)
        name = Text("BISCUITS", along=ring, size=14 mm, font="serif:Bold", fill=true)
        est = Text("EST. 2026", along=ring, flip=true, size=8 mm, font="serif")
    }
    At(lid_art.ring.center, box.lid.bb.center)
    CutInto(lid_art, box.lid)

    solid knob_top {
        disc = Circle(center=(0, 0), diameter=knob_d)
        drawing dots {
            d = Circle(center=(16, 0), diameter=4 mm, fill=true)
            CircularPattern(d, 8, (0, 0))
        }
    }
    solid knob_neck {
        disc = Circle(center=(0, 0), diameter=neck_d)
    }
    RightOf(knob_top, box, gap=10 mm)
    AlignTop(knob_top, box)
    Below(knob_neck, knob_top, gap=5 mm)
    AlignCenterX(knob_neck, knob_top)

    assert box.base.bb.width == 160 mm, "160 mm outside"
    assert box.base.bb.height == 160 mm, "160 mm outside"
    assert knob_top.disc.diameter == 45 mm, "45 mm knob"
    assert knob_neck.disc.diameter == 28 mm, "28 mm neck"
    assert ring_r - knob_d / 2 >= 5 mm, "lettering clear of the knob"
    assert lid_art.bb.width <= box_w - 2 * 3 mm - 10 mm, "lettering inside the wall with a margin"
}
