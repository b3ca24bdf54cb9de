# Request: a Telecaster-style control plate in 3 mm black acrylic, 140 x 32 mm with fully
# rounded ends. Measured from the neck end along the centre line: a 3.5 mm plate screw hole
# countersunk 7 mm at 7 mm; the 3-way switch's lever slot, 20 x 4.5 mm (rounded ends),
# centred at 32 mm, with its two 3 mm mounting-screw holes 34 mm apart centred on it; a
# 9.5 mm volume-pot hole at 72 mm and a 9.5 mm tone-pot hole at 110 mm; the second plate
# screw (3.5 mm, countersunk 7 mm) at 133 mm. "VOL" and "TONE" engraved (3.5 mm, reading
# up the plate, rotated 90 deg) on the far side of each pot towards the other, clear of the
# 19 mm knobs.

thickness 3 mm

W = 32 mm
LEN = 140 mm
KNOB_R = 19 mm / 2

solid control_plate {
    body = Slot(start=(W / 2, 0), end=(LEN - W / 2, 0), width=W)

    hole screws {
        a = Circle(center=(7, 0), diameter=3.5 mm)
        b = Circle(center=(133, 0), diameter=3.5 mm)
    }
    Countersink(screws, diameter=7 mm)

    hole switch {
        lever = Slot(center=(32, 0), length=20 mm, width=4.5 mm)
        m1 = Circle(center=(32 - 17, 0), diameter=3 mm)
        m2 = Circle(center=(32 + 17, 0), diameter=3 mm)
    }

    hole pots {
        vol = Circle(center=(72, 0), diameter=9.5 mm)
        tone = Circle(center=(110, 0), diameter=9.5 mm)
    }

    drawing labels {
        v = Text("VOL", position=(72 + KNOB_R + 3.5 mm, 0), size=3.5, rotation=90 deg,
                 valign="middle")
        t = Text("TONE", position=(110 - KNOB_R - 3.5 mm, 0), size=3.5, rotation=90 deg,
                 valign="middle")
    }

    assert body.bb.width == 140 mm and body.bb.height == 32 mm, "140 x 32 plate"
    assert screws.a.center.x - body.bb.left == 7 mm, "screw 7 mm from the neck end"
    assert screws.b.center.x - body.bb.left == 133 mm, "screw at 133 mm"
    assert switch.lever.center.x - body.bb.left == 32 mm, "switch slot at 32 mm"
    assert switch.m2.center.x - switch.m1.center.x == 34 mm, "switch screws 34 mm apart"
    assert pots.vol.center.x - body.bb.left == 72 mm, "volume at 72 mm"
    assert pots.tone.center.x - body.bb.left == 110 mm, "tone at 110 mm"
    # labels clear of the knobs
    assert labels.v.bb.left > pots.vol.center.x + KNOB_R, "VOL clear of the knob"
    assert labels.t.bb.right < pots.tone.center.x - KNOB_R, "TONE clear of the knob"
    assert labels.v.bb.right < labels.t.bb.left, "labels apart"
}
