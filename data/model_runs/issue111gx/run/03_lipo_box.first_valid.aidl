# Request: a storage box for my drone's LiPo batteries (kept in their fire bags), from 3 mm
# plywood: a finger-jointed box with a lift-off lid, 160 x 110 x 80 mm outside (lid included),
# 10 mm fingers.
# - the back wall has a cable slot for the balance leads: 40 mm long x 8 mm wide with round
#   ends, centred left-right, its top 15 mm below the wall's top edge;
# - the lid is vented: a grid of 4 rows x 8 columns of 6 mm holes at 12 mm pitch, centred on
#   the lid (cut through the lip under it too);
# - engraved on the lid: "LIPO STORAGE" 8 mm tall above the vents, baseline 30 mm above the
#   lid's centre, and "NEVER CHARGE UNATTENDED" 4 mm tall below them, baseline 35 mm below
#   the centre.

import "std/boxes.aidl"

units mm
thickness 3 mm

assembly lipo_box {
    box = lid_box(length=160 mm, width=110 mm, height=80 mm, thickness=3 mm, finger=10 mm)

    hole cable {
        s = Slot(center=(0, 0), length=40, width=8)
    }
    AlignCenterX(cable, box.body.back)
    cable.bb.top == box.body.back.bb.top - 15 mm
    CutInto(cable, box.body.back)

    hole vent {
        c = Circle(center=(0, 0), diameter=6)
    }
    vents = GridPattern(vent, 4, 8, 12)
    At(vent.c.center, box.lid.bb.center, dx=-42, dy=-18)
    CutInto(vent, box.lid)

    hole lip_vent {
        c = Circle(center=(0, 0), diameter=6)
    }
    lip_vents = GridPattern(lip_vent, 4, 8, 12)
    At(lip_vent.c.center, box.lip.bb.center, dx=-42, dy=-18)
    CutInto(lip_vent, box.lip)

    drawing title {
        t = Text("LIPO STORAGE", position=(0, 0), size=8)
    }
    At(title.t.position, box.lid.bb.center, dy=30)
    CutInto(title, box.lid)

    drawing warning {
        t = Text("NEVER CHARGE UNATTENDED", position=(0, 0), size=4)
    }
    At(warning.t.position, box.lid.bb.center, dy=-35)
    CutInto(warning, box.lid)

    assert box.length == 160 mm and box.width == 110 mm and box.height == 80 mm, "160 x 110 x 80 outside"
    assert cable.s.length == 40 mm and cable.s.width == 8 mm, "cable slot 40 x 8"
    assert box.body.back.bb.top - cable.bb.top == 15 mm, "slot 15 mm below the wall's top"
    assert len(vents) == 32 and len(lip_vents) == 32, "4 x 8 vents"
    assert distance(title, vents) >= 3 mm, "title clear of the vents"
    assert distance(warning, vents) >= 3 mm, "warning clear of the vents"
}
