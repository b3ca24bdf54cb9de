# Request (electronics): a base for my soldering helping hands. A closed finger-jointed box,
# 160 x 100 x 40 mm outside, 3 mm ply, 10 mm fingers, to be filled with sand for weight. The top
# (lid, glued on) has four 6.5 mm holes 15 mm in from each corner for the flexible arms (1/4 in
# threaded ends, nut inside), a 56 mm hole 20 mm right of centre for a brass tip cleaner, a
# 40 x 8 mm slot 38 mm left of centre to park tweezers, "HELPING HANDS" engraved along the front
# edge and "TIP CLEANER" above the cleaner's hole. The back has a 12 mm hole, centred, for the
# LED lamp's USB cable.

import "std/joints.aidl"

units mm
thickness 3 mm

assembly station {
    box = finger_box(length=160 mm, depth=100 mm, height=40 mm, thickness=3 mm, finger=10 mm,
                     closed=true)

    hole arms {
        for i in range(2) {
            for j in range(2) {
                c = Circle(center=(-65 + 130 * i, -35 + 70 * j), diameter=6.5)
            }
        }
    }
    CenterInside(arms, box.lid)
    CutInto(arms, box.lid)

    hole cleaner { c = Circle(center=(20, 0), diameter=56) }
    At(cleaner.c.center, box.lid.outline.center, dx=20)
    CutInto(cleaner, box.lid)

    hole park { s = Slot(center=(-38, 0), length=40, width=8, rotation=90 deg) }
    At(park.s.center, box.lid.outline.center, dx=-38)
    CutInto(park, box.lid)

    drawing label {
        t = Text("HELPING HANDS", position=(0, -43), size=5)
        u = Text("TIP CLEANER", position=(20, 31), size=3.5)
    }
    At(label.t.position, box.lid.outline.center, dy=-43)
    CutInto(label, box.lid)

    hole usb { c = Circle(center=(0, 0), diameter=12) }
    At(usb.c.center, box.back.outline.center)
    CutInto(usb, box.back)

    assert box.lid.outline.bb.width == 160 mm and box.lid.outline.bb.height == 100 mm, "160 x 100 top"
    assert len(arms.c) == 2 and len(arms.c[0]) == 2, "four arm holes"
    assert arms.c[0][0].center.x - box.lid.outline.bb.left == 15 mm, "arm holes 15 mm in (x)"
    assert arms.c[0][0].center.y - box.lid.outline.bb.bottom == 15 mm, "arm holes 15 mm in (y)"
    assert box.lid.outline.bb.right - arms.c[1][1].center.x == 15 mm, "arm holes 15 mm in (x, right)"
    assert box.lid.outline.bb.top - arms.c[1][1].center.y == 15 mm, "arm holes 15 mm in (y, top)"
    assert cleaner.c.center.x - box.lid.outline.center.x == 20 mm, "cleaner 20 mm right of centre"
    assert box.lid.outline.center.x - park.s.center.x == 38 mm, "tweezer slot 38 mm left of centre"
    assert park.s.length == 40 mm and park.s.width == 8 mm, "40 x 8 slot"
    assert label.u.position.y > cleaner.c.bb.top, "label above the cleaner hole"
}
