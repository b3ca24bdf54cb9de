# Request: a wall key cabinet for the hallway, 6 mm birch ply. Outside 200 mm wide,
# 250 mm tall, 60 mm deep (50 was asked first: the pin hinge needs 60), finger-jointed, with a flap door hinged along the top edge on
# pins cut from the sheet (it falls shut by its own weight). On the back panel: two
# rows of 4 brass cup hooks (2 mm pilot holes), 42 mm apart across, the rows 95 mm apart,
# the top row 45 mm below the inside top; each hook gets an engraved 5 mm label 8 mm above
# it (HOUSE, CAR, SHED, GARAGE / BIKE, OFFICE, SPARE, MUM). Two keyholes for wall screws
# (8 mm head, 4 mm slot), 150 mm apart, 20 mm below the inside top. The door has "KEYS"
# cut right through in 40 mm bold stencil letters (the keys show through) and a 4 mm hole
# for a small knob, 20 mm up from its bottom edge, centred.

import "std/boxes.aidl"
import "std/plates.aidl"
import "std/fasteners.aidl"

thickness 6 mm

names = ["HOUSE", "CAR", "SHED", "GARAGE", "BIKE", "OFFICE", "SPARE", "MUM"]
pitch = 42 mm
row_gap = 95 mm

assembly key_cabinet {
    k = hinged_box(length=200 mm, width=250 mm, height=60 mm, thickness=6 mm, finger=15 mm)

    # cup-hook pilot holes: 2 rows of 4, drawn about the back panel's centre
    hole hooks {
        for i in range(8) {
            hk = Circle(center=(-1.5 * pitch + (i % 4) * pitch, 70 - (i // 4) * row_gap), diameter=2)
        }
    }
    drawing labels {
        for i in range(8) {
            t = Text(names[i], position=(-1.5 * pitch + (i % 4) * pitch, 78 - (i // 4) * row_gap),
                     size=5, anchor="middle")
        }
    }
    left_key = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg)
    right_key = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg)

    hole word {
        t = Text("KEYS", position=(0, 0), size=40, font="sans:Bold", stencil=true,
                 valign="middle")
    }
    knob = clearance_hole(size=4)

    # the hooks: centred across the back, top row 45 below the inside top (6 mm wall)
    AlignCenterX(hooks, k.bottom)
    hooks.hk[0].center.y == k.bottom.bb.top - 6 mm - 45 mm
    for i in range(8) {
        At(labels.t[i].position, hooks.hk[i].center, dy=8)
    }
    # keyholes: 150 apart, centred, 20 below the inside top
    left_key.head_hole.center.y == k.bottom.bb.top - 6 mm - 20 mm
    At(right_key.head_hole.center, left_key.head_hole.center, dx=150)
    (left_key.head_hole.center.x + right_key.head_hole.center.x) / 2 == k.bottom.bb.center_x

    # the door (lid): the word centred, the knob hole 20 up from the front edge
    CenterInside(word, k.lid)
    AlignCenterX(knob, k.lid)
    knob.c.center.y == k.lid.bb.bottom + 20 mm

    CutInto(hooks, k.bottom)
    CutInto(labels, k.bottom)
    CutInto(left_key, k.bottom)
    CutInto(right_key, k.bottom)
    CutInto(word, k.lid)
    CutInto(knob, k.lid)

    # the request's numbers
    assert len(hooks.hk) == 8, "8 hooks"
    assert hooks.hk[1].center.x - hooks.hk[0].center.x == 42 mm, "hooks 42 apart"
    assert hooks.hk[0].center.y - hooks.hk[4].center.y == 95 mm, "rows 95 apart"
    assert k.bottom.bb.top - 6 mm - hooks.hk[0].center.y == 45 mm, "top row 45 below inside top"
    assert labels.t[5].position.y - hooks.hk[5].center.y == 8 mm, "label 8 above its hook"
    assert right_key.head_hole.center.x - left_key.head_hole.center.x == 150 mm, "keyholes 150 apart"
    assert k.bottom.bb.top - 6 mm - left_key.head_hole.center.y == 20 mm, "keyholes 20 below inside top"
    assert knob.c.center.y - k.lid.bb.bottom == 20 mm, "knob 20 up"
    assert distance(labels, left_key) >= 3 mm, "labels clear of the keyholes"
    assert distance(labels, right_key) >= 3 mm, "labels clear of the keyholes"
    assert word.bb.width <= k.lid.bb.width - 30 mm, "KEYS leaves a margin"
}
