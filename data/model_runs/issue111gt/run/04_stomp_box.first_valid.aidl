# Request (music): a heel stomp box for busking, 6 mm birch ply.
# - A closed finger-jointed box 250 mm long x 180 mm deep x 70 mm high (outside), 20 mm
#   fingers; the lid is the face I stomp on.
# - "STOMP" engraved filled in 30 mm bold letters in the middle of the lid.
# - A 45 mm sound hole in the middle of the back panel.
# - A 9.5 mm hole in the middle of the right-hand side for the 1/4" jack socket of the piezo.
# - Four 3.5 mm holes in the bottom, 15 mm in from each edge at the corners, for the
#   screws of rubber feet.

import "std/joints.aidl"

t = 6 mm
thickness t

assembly stomp {
    box = finger_box(length=250 mm, depth=180 mm, height=70 mm, thickness=t, finger=20 mm,
                     closed=true, outside=true)

    drawing label {
        word = Text("STOMP", position=(0, 0), size=30, font="sans:Bold", valign="middle",
                    fill=true)
    }
    CenterInside(label, box.lid.core)
    CutInto(label, box.lid)

    hole sound { c = Circle(center=(0, 0), diameter=45) }
    CenterInside(sound, box.back.outline)
    CutInto(sound, box.back)

    hole jack { c = Circle(center=(0, 0), diameter=9.5) }
    CenterInside(jack, box.right.outline)
    CutInto(jack, box.right)

    hole foot { c = Circle(center=(0, 0), diameter=3.5) }
    feet = CornerPattern(foot, box.bottom.outline, inset=15 mm)
    CutInto(foot, box.bottom)

    # the request's numbers
    assert box.front.outline.width == 250 mm and box.front.outline.height == 70 mm,
        "250 long, 70 high"
    assert box.left.outline.height == 180 mm and box.left.outline.width == 70 mm, "180 deep"
    assert box.lid.outline.width == 250 mm and box.lid.outline.height == 180 mm, "lid 250 x 180"
    assert sound.c.diameter == 45 mm and jack.c.diameter == 9.5 mm, "45 mm sound hole, 9.5 mm jack"
    assert distance(sound.c.center, box.back.outline.center) < 0.01 mm, "sound hole centred"
    assert distance(jack.c.center, box.right.outline.center) < 0.01 mm, "jack hole centred"
    assert distance(label.word.center, box.lid.outline.center) < 1 mm, "STOMP in the middle"
    assert len(feet) == 4, "four feet"
    assert feet[0].c.center.x - box.bottom.outline.bb.left == 15 mm, "feet 15 in"
    assert feet[0].c.center.y - box.bottom.outline.bb.bottom == 15 mm, "feet 15 in"
    assert label.bb.width <= box.lid.core.bb.width and label.bb.height <= box.lid.core.bb.height,
        "STOMP clear of the joints"
    assert distance(sound, box.back.core) >= 0 mm, "sound hole in the panel"
}
