# Request: "A wooden tongue drum: a closed finger-jointed box 240 x 160 x 100 mm outside in
# 4 mm birch ply (12 mm fingers). Six tongues in the top, each 30 mm wide, freed by a 2 mm
# U-shaped slit: three rooted 10 mm in from the front wall pointing back (C 70, D 64, E 58 mm
# long, left to right) and three rooted 10 mm in from the back wall pointing forward (C' 40,
# A 46, G 52 mm long, left to right), in three columns 70 mm apart, so each column is an H.
# Engrave each tongue's note (8 mm letters) 12 mm from its free end. A 50 mm sound hole in
# the middle of the bottom."

import "std/joints.aidl"

thickness 4 mm

t = 4 mm
len_box = 240 mm
depth = 160 mm
tall = 100 mm
tw = 30 mm           # tongue width
slit = 2 mm
root = depth / 2 - t - 10 mm     # from the lid's middle to a tongue's root
xs = [-70 mm, 0 mm, 70 mm]
front_len = [70 mm, 64 mm, 58 mm]
front_note = ["C", "D", "E"]
back_len = [40 mm, 46 mm, 52 mm]
back_note = ["C'", "A", "G"]

assembly drum {
    box = finger_box(length=len_box, depth=depth, height=tall, thickness=t, finger=12 mm)

    hole tongues {
        for i in range(3) {
            f = Stroke(Polyline([(xs[i] - tw / 2, -root), (xs[i] - tw / 2, -root + front_len[i]),
                                 (xs[i] + tw / 2, -root + front_len[i]), (xs[i] + tw / 2, -root)]),
                       width=slit)
            b = Stroke(Polyline([(xs[i] - tw / 2, root), (xs[i] - tw / 2, root - back_len[i]),
                                 (xs[i] + tw / 2, root - back_len[i]), (xs[i] + tw / 2, root)]),
                       width=slit)
        }
    }
    drawing notes {
        for i in range(3) {
            fn = Text(front_note[i], position=(xs[i], -root + front_len[i] - 12 mm), size=8,
                      valign="middle")
            bn = Text(back_note[i], position=(xs[i], root - back_len[i] + 12 mm), size=8,
                      valign="middle")
        }
    }
    Rigid(tongues, notes)
    CenterInside(tongues, box.lid)
    CutInto(tongues, box.lid)
    CutInto(notes, box.lid)

    hole sound { c = Circle(center=(0, 0), diameter=50) }
    CenterInside(sound, box.bottom)
    CutInto(sound, box.bottom)

    assert box.lid.outline.bb.width == 240 mm and box.lid.outline.bb.height == 160 mm,
        "240 x 160 top"
    assert box.front.outline.bb.height == 100 mm, "100 mm tall"
    assert len(tongues.f) == 3 and len(tongues.b) == 3, "six tongues"
    assert tongues.f[0].bb.width - slit == 30 mm, "30 mm tongues"
    assert tongues.f[0].bb.height - slit == 70 mm, "C tongue 70 mm"
    assert tongues.b[2].bb.height - slit == 52 mm, "G tongue 52 mm"
    assert xs[1] - xs[0] == 70 mm, "columns 70 mm apart"
    assert sound.c.diameter == 50 mm, "50 mm sound hole"
}
