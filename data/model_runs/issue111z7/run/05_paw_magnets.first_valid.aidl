# Pets: four paw-print fridge magnets of 3 mm acrylic, one per pet. Each is a 50 mm disc
# with a paw print cut through it: a pad 24 mm wide x 18 mm tall (the hull of two 12 mm
# circles and a 14 mm one) and four oval toes 7 x 10 mm pointing out from the pad,
# the inner two at 20 deg and the outer two at 55 deg either side of up, their centres 18 mm
# from the pad's big circle; the pet's name engraved round the bottom of the disc, 4 mm
# letters reading left to right. Names: MILO, LUNA, BELLA, MAX. Laid out 2 x 2, 55 mm apart.

thickness 3 mm

param disc_d = 50 mm, min = 40 mm, max = 70 mm

names = ["MILO", "LUNA", "BELLA", "MAX"]
toe_angles = [-55 deg, -20 deg, 20 deg, 55 deg]
pad_c = (0, -4 mm)

def paw_magnet(name="PET") -> solid {
    disc = Circle(center=(0, 0), diameter=disc_d)
    hole paw {
        pad = Hull(Circle(center=(-6 mm, -9 mm), radius=6 mm), Circle(center=(6 mm, -9 mm), radius=6 mm),
                   Circle(center=pad_c, radius=7 mm))
        for a in toe_angles {
            toe = Ellipse(center=(-18 mm * sin(a), -4 mm + 18 mm * cos(a)), rx=5 mm, ry=3.5 mm,
                          rotation=90 deg - a)
        }
    }
    drawing label {
        ring = Circle(center=(0, 0), radius=disc_d / 2 - 4 mm, construction=true)
        t = Text(name, along=ring, size=4 mm, flip=true)
    }
}

assembly magnets {
    for i in range(4) {
        m = paw_magnet(name=names[i])
    }
    for i in range(4) {
        m[i].disc.center.x == (i % 2) * 55 mm
        m[i].disc.center.y == -(i // 2) * 55 mm
    }

    assert len(m) == 4, "four magnets"
    assert m[0].disc.diameter == 50 mm, "50 mm discs"
    assert m[0].paw.pad.bb.width == 24 mm and m[0].paw.pad.bb.height == 18 mm, "pad 24 x 18"
    assert len(m[0].paw.toe) == 4, "four toes"
    assert m[0].paw.toe[1].rx * 2 == 10 mm and m[0].paw.toe[1].ry * 2 == 7 mm, "toes 7 x 10"
    assert m[0].label.t.size == 4 mm, "4 mm names"
    assert m[1].disc.center.x - m[0].disc.center.x == 55 mm, "55 mm apart"
}
