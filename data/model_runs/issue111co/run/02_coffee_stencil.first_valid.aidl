# Request: a cappuccino dusting stencil for my espresso corner. A 110 mm disc
# that rests on the cup's rim, with a handle 50 mm long and 30 mm wide (round
# end, 8 mm hole to hang it on a hook, "FOAM" engraved on it). Cut through the
# disc: a heart 44 mm wide a little above the middle, the word "AMORE" in
# stencil letters under it, and a ring of 12 dots, 5 mm each, on a 76 mm circle.
# 1 mm food-safe acrylic.

units mm
thickness 1 mm

param disc_d = 110 mm, min = 90 mm, max = 140 mm
param heart_w = 44 mm, min = 30 mm, max = 56 mm
param dots = 12, min = 6, max = 20
param dot_d = 5 mm, min = 3 mm, max = 7 mm
param ring_d = 76 mm, min = 70 mm, max = 84 mm

k = heart_w / 34 mm          # the prompt's heart is 34 mm wide
heart_up = 8 mm              # heart's centre line above the disc centre

def dot() -> hole {
    c = Circle(center=(0, ring_d / 2), diameter=dot_d)
}

solid stencil {
    disc = Circle(center=(0, 0), diameter=disc_d)
    handle = RoundedRectangle(center=(disc_d / 2 + 25 - 5, 0), width=60, height=30,
                              corner_radii=[0, 15, 15, 0])
    hole hang {
        c = Circle(center=(disc_d / 2 + 50 - 15, 0), diameter=8)
    }

    hole heart {
        l = Hull(Circle(center=(-8 * k, 5 * k + heart_up), radius=9 * k),
                 Point(0, -16 * k + heart_up))
        r = Hull(Circle(center=(8 * k, 5 * k + heart_up), radius=9 * k),
                 Point(0, -16 * k + heart_up))
    }

    hole word {
        w = Text("AMORE", position=(0, -22), size=9, font="sans:Bold", stencil=true)
    }

    first = dot()
    ring = CircularPattern(first, dots, disc.center)

    drawing label {
        t = Text("FOAM", position=(disc_d / 2 + 17, 0), size=5, valign="middle")
    }

    assert disc.diameter == 110 mm, "110 mm disc"
    assert handle.bb.right - disc.bb.right == 50 mm, "handle 50 mm long"
    assert handle.bb.height == 30 mm, "handle 30 mm wide"
    assert hang.c.diameter == 8 mm, "8 mm hanging hole"
    assert heart.bb.width == 44 mm, "heart 44 mm wide"
    assert heart.bb.center_y > disc.center.y, "heart a little above the middle"
    assert word.bb.top < heart.bb.bottom, "AMORE under the heart"
    assert len(ring) == 12, "12 dots"
    assert first.c.diameter == 5 mm, "5 mm dots"
    assert distance(first.c.center, disc.center) == 38 mm, "on a 76 mm circle"
}
