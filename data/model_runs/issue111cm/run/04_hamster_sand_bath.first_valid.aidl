# Request: a sand bath for a Syrian hamster, from 4 mm poplar plywood (no finish inside).
# A finger-jointed box 220 x 150 mm and 120 mm tall outside, with a lift-off lid (the lid
# has a lip under it so it stays put) for scooping out the sand. A 70 mm round doorway in
# the front, its bottom 25 mm above the inside floor so the sand stays in, its centre 60 mm
# from the front's left edge. "SAND BATH" engraved filled, bold sans 10 mm, centred in the
# space right of the door at the door's height. 15 air holes of 8 mm in 3 rows of 5 at
# 25 mm spacing, centred on the lid, through the lid and the lip alike.

import "std/boxes.aidl"

thickness 4 mm

t = 4 mm
door_d = 70 mm
sill = 25 mm            # door bottom above the inside floor
vent_d = 8 mm
pitch = 25 mm

assembly sand_bath {
    box = lid_box(length=220 mm, width=150 mm, height=120 mm, thickness=t, finger=12 mm)

    hole door { c = Circle(center=(0, 0), diameter=door_d) }
    door.c.bb.bottom == box.body.front.bb.bottom + t + sill
    door.c.center.x == box.body.front.bb.left + 60 mm
    CutInto(door, box.body.front)

    drawing sign {
        words = Text("SAND BATH", position=(0, 0), size=10 mm, font="sans:Bold",
                     valign="middle", fill=true)
    }
    AlignCenterY(sign, door)
    sign.bb.center_x == (door.bb.right + box.body.front.bb.right) / 2
    CutInto(sign, box.body.front)

    hole vent { c = Circle(center=(0, 0), diameter=vent_d) }
    vents = GridPattern(vent, 3, 5, (pitch, pitch))
    At(vent.c.center, box.lid.bb.center, dx=-2 * pitch, dy=-pitch)
    CutInto(vent, box.lid)

    hole lip_vent { c = Circle(center=(0, 0), diameter=vent_d) }
    lip_vents = GridPattern(lip_vent, 3, 5, (pitch, pitch))
    At(lip_vent.c.center, box.lip.bb.center, dx=-2 * pitch, dy=-pitch)
    CutInto(lip_vent, box.lip)

    assert box.length == 220 mm and box.width == 150 mm and box.height == 120 mm,
        "220 x 150 x 120 outside"
    assert door.c.diameter == 70 mm, "70 mm doorway"
    assert door.c.bb.bottom - (box.body.front.bb.bottom + t) == 25 mm, "sill 25 mm"
    assert len(vents) == 15 and len(lip_vents) == 15, "15 air holes in lid and lip"
    assert door.c.bb.top < box.body.front.bb.top - t, "the door stays below the top edge"
}
