# Sourdough starter jar lid (kitchen). Full sizes: a disc 90 mm in diameter, 4 mm ply, that
# lies on a jar's mouth. Twelve 4 mm vent holes evenly round a 25 mm radius circle about the
# centre, the first straight to the right (+x). A 5 mm hole in the centre for a knob's
# flat-head screw, countersunk 10 mm. "SOURDOUGH" engraved 6 mm high along an arc over the
# top, its baseline on a 33 mm radius about the centre, reading left to right. An engraved
# ring 4 mm inside the edge (41 mm radius).

import "std/plates.aidl"

units mm
thickness 4 mm

solid lid {
    disc = Circle(center=(0, 0), diameter=90)

    hole vent {
        v = Circle(center=(25, 0), diameter=4)
    }
    vents = CircularPattern(vent, 12, disc.center)
    Coincident(vent.v.center, polar(disc.center, 25, 0 deg))

    hole knob {
        c = Circle(center=(0, 0), diameter=5)
    }
    Concentric(knob.c, disc)
    Countersink(knob, diameter=10)

    word = text_on_arc(text="SOURDOUGH", radius=33 mm, size=6 mm, angle=90 deg, cx=0, cy=0)

    drawing rim {
        ring = Circle(center=(0, 0), radius=41)
    }
    Concentric(rim.ring, disc)

    assert disc.diameter == 90 mm, "90 mm disc"
    assert len(vents) == 12, "twelve vents"
    assert vent.v.diameter == 4 mm, "4 mm vents"
    assert distance(vent.v.center, disc.center) == 25 mm, "vents on r 25"
    assert vent.v.center.y == disc.center.y and vent.v.center.x > disc.center.x, "first vent to the right"
    assert knob.c.diameter == 5 mm, "5 mm knob hole"
    assert knob.c.center.x == disc.center.x and knob.c.center.y == disc.center.y, "knob hole central"
    assert len(word.ch) == 9, "nine letters"
    assert rim.ring.radius == 41 mm, "ring 4 mm inside the edge"
    assert word.bb.top < rim.ring.center.y + 41 mm, "letters inside the ring"
    assert min([distance(c.position, disc.center) for c in word.ch]) > 27 mm, "letters clear of the vents"
}
