# Request: a wall-hung dispenser for plastic carrier bags, for inside a kitchen cupboard
# door or on the wall, cut from 4 mm ply. An open-top finger-jointed box, outside
# 140 mm wide x 110 mm deep x 360 mm tall, 20 mm fingers: bags are stuffed in at the top and
# pulled out one at a time through a 75 mm round hole in the front, its centre 60 mm above
# the box's bottom edge and centred across. Two keyholes in the back (9 mm head, 4.5 mm
# slot, 10 mm long, pointing up) 80 mm apart, centred across, their heads 50 mm below the
# top edge, reached from the open top. On the front, "BAGS" in bold letters 30 mm tall,
# engraved filled, its baseline 250 mm above the bottom edge, and "REUSE ME" engraved in
# 8 mm strokes 20 mm under it.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 4 mm

assembly bag_dispenser {
    box = finger_box(length=140 mm, depth=110 mm, height=360 mm, thickness=4 mm,
                     finger=20 mm, closed=false)

    hole pull {
        c = Circle(center=(0, 0), diameter=75 mm)
    }
    AlignCenterX(pull, box.front.outline)
    pull.c.center.y == box.front.outline.bb.bottom + 60 mm
    CutInto(pull, box.front)

    hole hang {
        k1 = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg,
                     cx=-40 mm, cy=0 mm)
        k2 = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg,
                     cx=40 mm, cy=0 mm)
    }
    hang.k1.head_hole.center.x + hang.k2.head_hole.center.x == 2 * box.back.outline.bb.center_x
    hang.k1.head_hole.center.y == box.back.outline.bb.top - 50 mm
    CutInto(hang, box.back)

    drawing label {
        word = Text("BAGS", position=(0, 0), size=30 mm, font="sans:Bold", fill=true)
        sub = Text("REUSE ME", position=(0, -20 mm), size=8 mm)
    }
    label.word.position.x == box.front.outline.bb.center_x
    label.word.position.y == box.front.outline.bb.bottom + 250 mm
    CutInto(label, box.front)

    # the request's numbers
    assert box.front.outline.bb.width == 140 mm and box.front.outline.bb.height == 360 mm,
        "front 140 x 360"
    assert box.left.outline.bb.height == 110 mm, "110 mm deep"
    assert pull.c.diameter == 75 mm, "75 mm pull hole"
    assert pull.c.center.y - box.front.outline.bb.bottom == 60 mm, "pull hole 60 mm up"
    assert hang.k2.head_hole.center.x - hang.k1.head_hole.center.x == 80 mm, "keyholes 80 apart"
    assert box.back.outline.bb.top - hang.k1.head_hole.center.y == 50 mm, "keyholes 50 down"
    assert label.word.position.y - label.sub.position.y == 20 mm, "REUSE ME 20 mm under"
    # the pull hole stays clear of the bottom's fingers and the sides' corners
    assert pull.c.center.y - 75 mm / 2 - box.front.outline.bb.bottom >= 4 mm + 10 mm,
        "pull hole 10 mm above the floor"
}
