# Request (camping): a flat-pack mug tree for the camp kitchen table, from 6 mm birch ply, that
# slots together without glue and packs flat in the crate.
# - Two identical-looking posts 240 mm tall and 40 mm wide, each with splayed feet at the bottom
#   (160 mm across, 40 mm high, tapering into the post) so the tree stands on four feet.
# - The posts cross-halve into each other at right angles: one slotted 120 mm down from the top,
#   the other 120 mm up from the bottom, slots 6 mm wide.
# - Each post has two mug arms, one each side, 12 mm thick, rising at about 30 degrees with an
#   upturned tip so a mug can't slide off; the first post's arms spring from 200 mm up, the
#   second's from 150 mm up, so the four mugs hang at two heights.
# - "CAMP" engraved 10 mm tall up the first post below its slot, "MUGS" up the second above its.

import "std/joints.aidl"

thickness 6 mm

param t = 6 mm, min = 3 mm, max = 9 mm
param tall = 240 mm, min = 200 mm, max = 300 mm

def post(arm_h=200 mm, from_top=true, word="CAMP", word_y=80 mm) -> solid {
    stem = Rectangle(bottom_left=(-20, 0), width=40, height=tall)
    feet = Trapezoid(center=(0, 20), bottom_width=160, top_width=40, height=40)
    axis = Line((0, 0), (0, tall), construction=true)
    arm_r = Stroke(Polyline([(20, arm_h), (60, arm_h + 22), (64, arm_h + 32)]), width=12)
    arm_l = Mirrored(arm_r, axis)
    if from_top {
        halve = cross_halving(depth=tall / 2, thickness=t, cx=0 mm, cy=tall)
    } else {
        halve = cross_halving(depth=tall / 2, thickness=t, rotation=180 deg, cx=0 mm, cy=0 mm)
    }
    drawing label {
        w = Text(word, (0, word_y), size=10, rotation=90, valign="middle")
    }
}

assembly mug_tree {
    first = post(arm_h=200 mm, from_top=true, word="CAMP", word_y=80 mm)
    second = post(arm_h=150 mm, from_top=false, word="MUGS", word_y=185 mm)

    RightOf(second, first, gap=10)
    AlignBottom(second, first)
    # standing up, crossed at right angles on their centre lines
    Place(first, rotation=(90 deg, 0, 0), position=(0, t / 2, 0))
    Place(second, rotation=(90 deg, 0, 90 deg), position=(-t / 2, 0, 0))

    # the request's numbers
    assert first.stem.bb.height == 240 mm and first.stem.bb.width == 40 mm, "posts 240 x 40"
    assert first.feet.bb.width == 160 mm and first.feet.bb.height == 40 mm, "feet 160 across, 40 high"
    assert first.halve.depth == 120 mm and second.halve.depth == 120 mm, "slots 120 mm"
    assert first.halve.depth + second.halve.depth == first.stem.bb.height, "the halvings meet"
    assert first.halve.thickness == 6 mm, "6 mm slots"
    assert first.arm_r.bb.bottom - first.stem.bb.bottom + 6 mm == 200 mm, "first arms from 200 up"
    assert second.arm_r.bb.bottom - second.stem.bb.bottom + 6 mm == 150 mm, "second arms from 150 up"
}
