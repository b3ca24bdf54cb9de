# Request (office): an after-hours key drop box for the office door, 6 mm ply, finger-jointed
# with a hinged lid, outside 180 mm long, 120 mm deep, 100 mm tall, 15 mm fingers. The lid has
# a 70 x 14 mm round-ended drop slot in its middle, "KEY DROP" engraved filled 14 mm tall with
# its middle 38 mm behind the slot's centre (towards the hinge) and "AFTER HOURS" (5 mm strokes)
# 20 mm behind it, readable from the front. A 19 mm cam lock goes through the lid, centred
# left to right, its centre 25 mm from the lid's front edge: a D hole 19 mm round with one flat
# 17.5 mm from the far side (flat toward the hinge) so the lock cannot turn. The box hangs on
# the wall by two keyholes in the back (9 mm head, 4.5 mm slot, 10 mm long, up), 100 mm apart,
# at the back panel's mid-height.

units mm
thickness 6 mm
import "std/boxes.aidl"
import "std/plates.aidl"

assembly key_drop {
    box = hinged_box(length=180 mm, width=120 mm, height=100 mm, thickness=6 mm, finger=15 mm)

    hole drop { s = Slot(center=(0, 0), length=70, width=14) }
    CenterInside(drop, box.lid)
    CutInto(drop, box.lid)

    drawing label {
        t = Text("KEY DROP", position=(0, 38), size=14, font="sans:Bold", valign="middle", fill=true)
        s = Text("AFTER HOURS", position=(0, 20), size=5, valign="middle")
    }
    AlignCenterX(label, box.lid)
    VerticalDistance(drop.s.center, label.s.position, 20)
    CutInto(label, box.lid)

    hole lock {
        c = Circle(center=(0, 0), diameter=19, construction=true)
        # the D: a 19 mm circle cut by a flat 17.5 mm from its far (front) side
        d = Intersect(Circle(center=(0, 0), diameter=19),
                      Rectangle(center=(0, -9.5 + 17.5 / 2), width=20, height=17.5))
    }
    AlignCenterX(lock, box.lid)
    lock.c.center.y == box.lid.bb.bottom + 25
    CutInto(lock, box.lid)

    k1 = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg)
    k2 = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg)
    k1.head_hole.center.x == box.back.bb.center_x - 50
    k2.head_hole.center.x == box.back.bb.center_x + 50
    k1.head_hole.center.y == box.back.bb.center_y
    k2.head_hole.center.y == box.back.bb.center_y
    CutInto(k1, box.back)
    CutInto(k2, box.back)

    # the request's numbers
    assert drop.s.length == 70 mm and drop.s.width == 14 mm, "drop slot 70 x 14"
    assert label.t.position.y - drop.s.center.y == 38 mm, "KEY DROP 38 mm behind the slot"
    assert label.s.position.y - drop.s.center.y == 20 mm, "AFTER HOURS 20 mm behind the slot"
    assert lock.c.center.y - box.lid.bb.bottom == 25 mm, "lock 25 mm from the lid's front edge"
    assert lock.d.bb.height == 17.5 mm and lock.d.bb.width == 19 mm, "D hole 19 round, 17.5 to the flat"
    assert k2.head_hole.center.x - k1.head_hole.center.x == 100 mm, "keyholes 100 mm apart"
    assert distance(lock, drop) >= 5 mm, "the lock clear of the slot"
    assert distance(label, drop) >= 3 mm, "the engraving clear of the slot"
    assert label.bb.top <= box.lid.bb.top - 10 mm, "the engraving on the lid, clear of the hinge"
}
