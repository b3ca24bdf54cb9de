# Request: "A twine dispenser to hang in the potting shed, holding a ball of jute twine:
# a finger-jointed box of 4 mm ply, 110 x 110 mm and 120 mm tall outside (lid included),
# 10 mm fingers, with a lift-off lid. The twine comes out through a 12 mm hole in the middle
# of the lid, and a 2 mm wide slit running 14 mm on from the hole's edge (toward the back)
# locks the loose end; the lid's lip under it has a 44 mm hole so the slit stays open below.
# The back has a keyhole (8 mm head, 4 mm slot 10 mm long, upward) centred 25 mm below its
# top edge to hang it on a screw. The word TWINE is engraved filled on the front, sans bold
# 20 mm tall, centred."

import "std/boxes.aidl"
import "std/plates.aidl"

units mm
thickness 4 mm

assembly dispenser {
    box = lid_box(length=110 mm, width=110 mm, height=120 mm, thickness=4 mm, finger=10 mm)

    # the lid: the twine hole and the locking slit, toward the back (+y on the flat lid)
    hole outlet {
        c = Circle(center=(0, 0), diameter=12)
        # the slot's end is its end arc's centre: the slit's tip lies 1 mm (its radius) beyond
        lock = Slot(start=(0, 0), end=(0, 6 + 14 - 1), width=2)
    }
    Concentric(outlet.c, box.lid.bb.center)
    CutInto(outlet, box.lid)

    hole lip_hole { c = Circle(center=(0, 0), diameter=44) }
    Concentric(lip_hole.c, box.lip.bb.center)
    CutInto(lip_hole, box.lip)

    # the back: a keyhole to hang it
    kh = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg)
    AlignCenterX(kh.head_hole, box.body.back)
    kh.head_hole.center.y == box.body.back.bb.top - 25 mm
    CutInto(kh, box.body.back)

    # the front: the engraved word
    drawing label {
        word = Text("TWINE", position=(0, 0), size=20, font="sans:Bold", valign="middle",
                    fill=true)
    }
    CenterInside(label, box.body.front)
    CutInto(label, box.body.front)

    # the request's numbers
    assert box.length == 110 mm and box.width == 110 mm and box.height == 120 mm, "box size"
    assert abs(outlet.c.diameter - 12 mm) < 0.01, "12 mm outlet"
    assert abs((outlet.lock.bb.top - outlet.c.bb.top) - 14 mm) < 0.01, "slit 14 mm past the hole"
    assert abs(outlet.lock.width - 2 mm) < 0.01, "slit 2 mm wide"
    assert abs(lip_hole.c.diameter - 44 mm) < 0.01, "44 mm hole in the lip"
    assert abs((box.body.back.bb.top - kh.head_hole.center.y) - 25 mm) < 0.01,
        "keyhole 25 mm below the top"
    assert abs(label.word.size - 20 mm) < 0.01, "letters 20 mm"
    # the word fits between the front's finger joints
    assert label.bb.width < box.body.front.bb.width - 2 * 4 mm - 10 mm, "word fits the front"
}
