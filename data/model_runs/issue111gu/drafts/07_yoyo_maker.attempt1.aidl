# Request: a set of fabric yo-yo (Suffolk puff) makers for my quilting group, from 3 mm
# ply, for finished puffs of about 35, 45 and 60 mm. For each size: a cutting template,
# a disc of 2 x size + 10 mm (80, 100, 130) with "CUT" and its diameter engraved filled;
# and a stitch plate, a disc of 2 x size (70, 90, 120) with notches round its rim about
# 6 mm apart (1.5 mm wide, reaching 5 mm in from the rim), so the hem folded over the rim
# is stitched through the notches and the plate lifts out; its size ("35") engraved filled
# 12 mm high in the middle. Every piece has a 5 mm hole 8 mm in from its rim at the top to
# keep the set on a ring, with no notch next to it.

units mm
thickness 3 mm

sizes = [35, 45, 60]

def n_notches(f) = round(2 * pi * (f - 2.5) / 6)

def cut_template(f=35) -> solid {
    disc = Circle(center=(0, 0), diameter=(2 * f + 10) * 1 mm)
    hole hang {
        c = Circle(center=(0, (f + 5 - 8) * 1 mm), diameter=5 mm)
    }
    drawing label {
        a = Text("CUT", position=(0, 5 mm), size=8 mm, font="sans:Bold", valign="middle",
                 fill=true)
        b = Text(f"{2 * f + 10:.0f}", position=(0, -8 mm), size=8 mm, font="sans:Bold",
                 valign="middle", fill=true)
    }
}

def stitch_plate(f=35) -> solid {
    disc = Circle(center=(0, 0), diameter=2 * f * 1 mm)
    hole hang {
        c = Circle(center=(0, (f - 8) * 1 mm), diameter=5 mm)
    }
    hole notch {
        s = Slot(center=(0, (f - 2) * 1 mm), length=6 mm, width=1.5 mm, rotation=90 deg)
    }
    notches = CircularPattern(notch, n_notches(f), (0, 0), start_angle=180 deg / n_notches(f))
    drawing label {
        a = Text(str(f), position=(0, 0), size=12 mm, font="sans:Bold", valign="middle",
                 fill=true)
    }
}

assembly yoyo_makers {
    for f in sizes {
        ct = cut_template(f=f)
        sp = stitch_plate(f=f)
    }

    # flat on the sheet: the templates in a row, the plates under them
    for i in range(1, 3) {
        RightOf(ct[i], ct[i - 1], gap=5 mm)
        AlignBottom(ct[i], ct[i - 1])
        RightOf(sp[i], sp[i - 1], gap=5 mm)
        AlignTop(sp[i], sp[i - 1])
    }
    Below(sp[0], ct[0], gap=5 mm)
    AlignLeft(sp[0], ct[0])

    assert ct[0].disc.diameter == 80 mm and ct[1].disc.diameter == 100 mm and
        ct[2].disc.diameter == 130 mm, "templates 80, 100, 130"
    assert sp[0].disc.diameter == 70 mm and sp[1].disc.diameter == 90 mm and
        sp[2].disc.diameter == 120 mm, "plates 70, 90, 120"
    for i in range(3) {
        assert distance(sp[i].notches[0].s.center, sp[i].notches[1].s.center) >= 5.5 mm and
            distance(sp[i].notches[0].s.center, sp[i].notches[1].s.center) <= 6.5 mm,
            "notches about 6 mm apart"
        assert sp[i].disc.radius - sp[i].notches[0].s.bb.bottom >= 0 mm, "notch reaches in"
        assert distance(sp[i].hang, sp[i].notches) >= 2 mm, "hanging hole clear of the notches"
        assert ct[i].disc.top.y - ct[i].hang.c.center.y == 8 mm and
            sp[i].disc.top.y - sp[i].hang.c.center.y == 8 mm, "hanging holes 8 mm in"
        assert distance(sp[i].label, sp[i].hang) >= 2 mm and
            distance(ct[i].label, ct[i].hang) >= 2 mm, "labels clear of the holes"
    }
}
