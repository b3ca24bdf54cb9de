# Kitchen: pizza slicing guide for a 30 cm pizza, 3 mm acrylic. A disc 320 mm in diameter
# with a 30 mm finger hole in the middle and 8 radial knife slots, 4 mm wide, running from
# 25 mm to 150 mm from the centre, set between the 8 slices at 22.5 + k * 45 deg. "PIZZA"
# in sans outline letters 10 mm tall engraved (filled) 100 mm above the centre.

thickness 3 mm

solid guide {
    disc = Circle(center=(0, 0), diameter=320)
    hole finger {
        c = Circle(center=(0, 0), diameter=30)
    }
    Concentric(finger.c, disc)

    hole slots {
        for k in range(8) {
            a = 22.5 deg + k * 45 deg
            s = Slot(start=(25 * cos(a), 25 * sin(a)), end=(146 * cos(a), 146 * sin(a)), width=4)
        }
    }
    for k in range(8) {
        Coincident(slots.s[k].start, polar(disc.center, 27, 22.5 deg + k * 45 deg))
        Coincident(slots.s[k].end, polar(disc.center, 148, 22.5 deg + k * 45 deg))
    }

    drawing label {
        word = Text("PIZZA", (0, 100), size=10, valign="middle", font="sans", fill=true)
    }
    AlignCenterX(label, disc)

    assert disc.diameter == 320 mm, "320 mm disc"
    assert finger.c.diameter == 30 mm, "30 mm finger hole"
    assert len(slots.s) == 8, "8 slots"
    assert slots.s[0].width == 4 mm, "slots 4 mm wide"
    assert abs(slots.bb.top - 150 mm * sin(112.5 deg) - 0) < 2.1 mm, "slots reach 150 mm"
}
