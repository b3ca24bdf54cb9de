# Request (garden): "A countertop compost caddy that holds a 3 L bin liner for kitchen scraps on
# their way to the heap, from 6 mm birch ply: a finger-jointed box 200 x 150 x 220 mm tall outside
# (lid included), fingers about 20 mm. A lift-off lid with a locating lip underneath; through lid
# and lip, a 60 x 22 mm finger slot in the middle to lift it and 24 vent holes 8 mm (two blocks of
# 2 rows x 6, 20 mm pitch, one in front of the slot and one behind it) over a charcoal pad. A 90 x
# 25 mm hand hold in each side wall, its top 25 mm below the wall's top edge, centred front to
# back. "COMPOST" fill-engraved across the front, at most 150 mm wide, in its upper half."

import "std/boxes.aidl"

thickness 6 mm
t = 6 mm

def lid_cuts() -> hole {
    grip = Slot(center=(0, 0), length=60, width=22)
    for r in range(4) {
        for c in range(6) {
            vent = Circle(center=(-50 + 20 * c, [-50, -30, 30, 50][r]), diameter=8)
        }
    }
}

def hand_hold() -> hole {
    s = Slot(center=(0, 0), length=90, width=25, rotation=90 deg)
}

assembly caddy {
    box = lid_box(length=200 mm, width=150 mm, height=220 mm, thickness=t, finger=20 mm)

    # the lid and its lip get the same openings
    lid_holes = lid_cuts()
    CenterInside(lid_holes, box.lid)
    CutInto(lid_holes, box.lid)
    lip_holes = lid_cuts()
    CenterInside(lip_holes, box.lip)
    CutInto(lip_holes, box.lip)

    # hand holds: a side lies on its side in the net, its top edge outward
    hold_l = hand_hold()
    AlignCenterY(hold_l, box.body.left)
    hold_l.bb.left == box.body.left.bb.left + 25 mm
    CutInto(hold_l, box.body.left)
    hold_r = hand_hold()
    AlignCenterY(hold_r, box.body.right)
    hold_r.bb.right == box.body.right.bb.right - 25 mm
    CutInto(hold_r, box.body.right)

    drawing label {
        word = Text("COMPOST", position=(0, 0), size=30, font="sans:Bold", valign="middle",
                    fill=true, max_width=150)
    }
    AlignCenterX(label, box.body.front)
    label.word.position.y == box.body.front.bb.top - 60 mm
    CutInto(label, box.body.front)

    # the request's numbers
    assert box.lid.bb.width == 200 mm and box.lid.bb.height == 150 mm, "lid 200 x 150"
    assert box.body.front.bb.width == 200 mm, "front 200 wide"
    assert box.body.front.bb.height + t == 220 mm, "220 tall with the lid"
    assert len(lid_holes.vent) == 4 and len(lid_holes.vent[0]) == 6, "2 x (2 rows of 6) vents"
    assert lid_holes.vent[0][0].diameter == 8 mm, "8 mm vents"
    assert lid_holes.vent[0][1].center.x - lid_holes.vent[0][0].center.x == 20 mm, "20 mm pitch"
    assert lid_holes.grip.length == 60 mm and lid_holes.grip.width == 22 mm, "finger slot 60 x 22"
    assert distance(lid_holes.grip, lid_holes.vent[1][0]) >= 3 mm, "web between slot and vents"
    assert lip_holes.bb.width < box.lip.bb.width - 10 mm and lip_holes.bb.height < box.lip.bb.height - 10 mm, "openings inside the lip"
    assert hold_l.bb.left - box.body.left.bb.left == 25 mm, "hand hold 25 mm below the top"
    assert hold_l.s.length == 90 mm and hold_l.s.width == 25 mm, "hand hold 90 x 25"
    assert label.bb.width <= 150 mm, "COMPOST at most 150 wide"
    assert label.bb.bottom >= box.body.front.bb.center_y, "in the front's upper half"
    assert box.body.front.bb.top - label.bb.top >= 20 mm, "clear of the top edge's fingers"
}
