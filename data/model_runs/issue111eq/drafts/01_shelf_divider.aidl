# Request: a freestanding divider for a wardrobe shelf, to keep stacks of jumpers apart.
# Cut from 5 mm clear acrylic. The upright is 300 mm tall and 260 mm deep (front to back),
# its top front corner rounded R40 and its top back corner R5; a 90 x 30 mm finger slot
# for lifting it sits 40 mm below the top, its centre 60 mm from the front edge. The word
# "JUMPERS" is engraved (filled, bold, 20 mm capitals) across the middle of the upright.
# Two feet, each 200 mm long and 40 mm tall with R8 top corners, stand crosswise under
# the upright 50 mm in from its front and back edges, cross-halved into it: the upright
# has two 20 mm slots up from its bottom edge, each foot a 20 mm slot down from the
# middle of its top edge, so the foot's top and the upright's bottom meet in the middle.

import "std/joints.aidl"

units mm
t = 5 mm
thickness t
kerf 0.15 mm

param depth = 260 mm, min = 180 mm, max = 400 mm
param height = 300 mm, min = 150 mm, max = 450 mm
foot_len = 200 mm
foot_h = 40 mm
foot_in = 50 mm       # each foot's centre line from the upright's front and back edges

def foot() -> solid {
    body = RoundedRectangle(center=(0, 20), width=200, height=40, corner_radii=[8, 8, 0, 0])
    notch = cross_halving(depth=20 mm, thickness=5 mm, cx=0 mm, cy=40 mm)
}

assembly divider {
    solid upright {
        body = RoundedRectangle(bottom_left=(0, 0), width=depth, height=height,
                                corner_radii=[5, 40, 0, 0])
        back_notch = cross_halving(depth=20 mm, thickness=5 mm, rotation=180 deg,
                                   cx=foot_in, cy=0 mm)
        front_notch = cross_halving(depth=20 mm, thickness=5 mm, rotation=180 deg,
                                    cx=depth - foot_in, cy=0 mm)
        hole grip {
            s = Slot(center=(depth - 60 mm, height - 40 mm), length=90, width=30)
        }
        drawing label {
            word = Text("JUMPERS", position=(depth / 2, height / 2), size=20,
                        font="sans:Bold", valign="middle", fill=true)
        }
        assert body.width == 260 mm, "260 mm deep"
        assert body.height == 300 mm, "300 mm tall"
        assert body.bb.right - grip.s.center.x == 60 mm, "finger slot centre 60 mm from the front"
        assert body.bb.top - grip.s.center.y == 40 mm, "finger slot 40 mm below the top"
        assert grip.s.length == 90 mm and grip.s.width == 30 mm, "finger slot 90 x 30"
        assert distance(label, grip) >= 5 mm, "label clear of the finger slot"
        assert label.bb.width <= body.width - 40 mm, "label inside the upright"
    }
    back_foot = foot()
    front_foot = foot()
    Below(back_foot, upright, gap=10)
    AlignLeft(back_foot, upright)
    Below(front_foot, back_foot, gap=10)
    AlignLeft(front_foot, upright)

    assert back_foot.body.width == 200 mm and back_foot.body.height == 40 mm, "feet 200 x 40"
    assert upright.back_notch.depth + back_foot.notch.depth == 40 mm,
        "the halvings add up to the foot's height"
    assert upright.back_notch.cx == 50 mm, "back foot 50 mm in from the back"
    assert depth - upright.front_notch.cx == 50 mm, "front foot 50 mm in from the front"

    # 3D: the upright stands in the x-z plane, its face to the front; the feet cross it
    Place(upright, position=(0, 0, 0), face="front", up="up")
    Place(back_foot, position=(foot_in - t / 2, -t / 2, 0), face="right", up="up")
    Place(front_foot, position=(depth - foot_in - t / 2, -t / 2, 0), face="right", up="up")
}
