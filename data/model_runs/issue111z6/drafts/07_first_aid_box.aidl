# Camping: a first-aid box from 3 mm plywood with a red acrylic cross inlaid in its lid.
# Finger-jointed lift-off-lid box (lid_box) 160 x 110 x 70 mm outside, 10 mm fingers.
# In the lid a cross-shaped opening 40 x 40 mm with 13 mm arms, centred left-right and
# 12 mm above the lid's centre; a separate cross of the same size (3 mm red acrylic,
# glued in, resting on the lid's lip; the laser's kerf is the glue gap). "FIRST AID"
# in bold sans 10 mm high, filled engraving, centred 30 mm below the lid's centre.

import "std/boxes.aidl"

thickness 3 mm

param cross = 40 mm, min = 25 mm, max = 60 mm
param arm = 13 mm, min = 8 mm, max = 20 mm

assembly kit {
    box = lid_box(length=160 mm, width=110 mm, height=70 mm, thickness=3 mm, finger=10 mm)

    hole cross_hole {
        h = Rectangle(center=(0, 0), width=cross, height=arm)
        v = Rectangle(center=(0, 0), width=arm, height=cross)
    }
    AlignCenterX(cross_hole, box.lid)
    cross_hole.bb.center_y == box.lid.bb.center_y + 12 mm
    CutInto(cross_hole, box.lid)

    drawing label {
        t = Text("FIRST AID", position=(0, 0), size=10, font="sans:Bold", valign="middle", fill=true)
    }
    AlignCenterX(label, box.lid)
    label.t.position.y == box.lid.bb.center_y - 30 mm
    CutInto(label, box.lid)

    solid inlay {
        h = Rectangle(center=(0, 0), width=cross, height=arm)
        v = Rectangle(center=(0, 0), width=arm, height=cross)
    }
    RightOf(inlay, box, gap=10)
    AlignCenterY(inlay, box)

    assert box.length == 160 mm and box.width == 110 mm and box.height == 70 mm, "160 x 110 x 70 outside"
    assert box.lid.bb.width == 160 mm and box.lid.bb.height == 110 mm, "lid covers the box"
    assert cross_hole.bb.width == 40 mm and cross_hole.bb.height == 40 mm, "cross 40 x 40"
    assert cross_hole.h.height == 13 mm and cross_hole.v.width == 13 mm, "13 mm arms"
    assert inlay.bb.width == cross_hole.bb.width and inlay.bb.height == cross_hole.bb.height, "inlay the hole's size"
    assert cross_hole.bb.center_x == box.lid.bb.center_x, "cross centred left-right"
}
