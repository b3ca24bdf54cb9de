# Request: a kitchen compost caddy from 4 mm birch ply (a bag liner goes inside): a
# finger-jointed box 220 mm long, 160 mm wide, 210 mm tall overall with a lift-off lid
# (12 mm fingers). The lid has a 70 x 22 mm finger-pull slot in its middle (along the length)
# and, either side of it, a vent field of 6 mm holes, 3 columns x 6 rows at 12 mm pitch,
# centred 65 mm left and right of the lid's centre (a charcoal filter pad is glued under the
# lid); the lip under the lid gets the same openings. Each end wall (the 160 mm sides) has a
# carrying hand hole 80 x 25 mm (rounded ends) running front to back, its top edge 30 mm below
# the wall's top. "COMPOST" fill-engraved on the front in bold letters 26 mm tall, centred.

import "std/boxes.aidl"

units mm
thickness 4 mm

def lid_cuts() -> hole {
    pull = Slot(center=(0, 0), length=70, width=22)
    v = Circle(center=(-77, -30), diameter=6)
    left_vents = GridPattern(v, 6, 3, 12)
    w = Circle(center=(53, -30), diameter=6)
    right_vents = GridPattern(w, 6, 3, 12)
}

assembly caddy {
    box = lid_box(length=220 mm, width=160 mm, height=210 mm, thickness=4 mm, finger=12 mm)

    top_cuts = lid_cuts()
    CenterInside(top_cuts, box.lid)
    CutInto(top_cuts, box.lid)
    lip_cuts = lid_cuts()
    CenterInside(lip_cuts, box.lip)
    CutInto(lip_cuts, box.lip)

    hole left_hand {
        s = Slot(center=(0, 0), length=80, width=25, rotation=90 deg)
    }
    left_hand.bb.left == box.body.left.bb.left + 30 mm
    AlignCenterY(left_hand, box.body.left)
    CutInto(left_hand, box.body.left)

    hole right_hand {
        s = Slot(center=(0, 0), length=80, width=25, rotation=90 deg)
    }
    right_hand.bb.right == box.body.right.bb.right - 30 mm
    AlignCenterY(right_hand, box.body.right)
    CutInto(right_hand, box.body.right)

    drawing label {
        t = Text("COMPOST", position=(0, 0), size=26, font="sans:Bold", valign="middle",
                 fill=true)
    }
    CenterInside(label, box.body.front)
    CutInto(label, box.body.front)

    assert box.lid.bb.width == 220 mm, "lid 220 long"
    assert box.lid.bb.height == 160 mm, "lid 160 wide"
    assert box.body.front.bb.width == 220 mm, "front 220 long"
    assert top_cuts.pull.length == 70 mm and top_cuts.pull.width == 22 mm, "70 x 22 pull"
    assert len(top_cuts.left_vents) == 18 and len(top_cuts.right_vents) == 18, "3 x 6 vents each side"
    assert top_cuts.right_vents[0].center.x - top_cuts.pull.center.x == 65 mm - 12 mm, "right field centred 65 mm right"
    assert top_cuts.pull.center.x - top_cuts.left_vents[0].center.x == 65 mm + 12 mm, "left field centred 65 mm left"
    assert distance(top_cuts.pull, top_cuts.right_vents[0]) >= 5 mm, "vents clear of the pull"
    assert left_hand.s.length == 80 mm and left_hand.s.width == 25 mm, "80 x 25 hand hole"
    assert label.t.size == 26 mm, "letters 26 mm"
}
