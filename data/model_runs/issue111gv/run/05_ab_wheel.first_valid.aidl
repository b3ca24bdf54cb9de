# Request: an ab roller wheel from three discs of 12 mm birch ply glued together (36 mm
# tread), spinning on a 20 mm hardwood dowel that is the handle. Outer discs 180 mm across,
# the middle one 168 mm, so a 6 mm deep channel holds a strip of bike inner tube as the
# tyre. Each disc: a 20.5 mm bore, six 32 mm lightening holes on a 55 mm radius, three
# 6 mm glue-up dowel holes on a 30 mm radius. The right-hand outer disc carries, engraved
# along its rim, "CORE ROLLER" over the top and "ANA 2026" under the bottom, 8 mm high.
# Two 6 mm ply spacer washers, 45 mm across with a 20.5 mm bore, one each side of the wheel.

import "std/shapes.aidl"

thickness 12 mm

ply = 12 mm
bore_d = 20.5 mm

def disc(d=180 mm, words=false) -> solid {
    rim = Circle(center=(0, 0), diameter=d)
    hole bore { c = Circle(center=(0, 0), diameter=bore_d) }
    hole light { c = Circle(center=(55, 0), diameter=32) }
    lights = CircularPattern(light, 6, (0, 0))
    for a in [30 deg, 150 deg, 270 deg] {
        hole pin { c = Circle(center=(30 mm * cos(a), 30 mm * sin(a)), diameter=6) }
    }
    if words {
        drawing rim_text {
            top_ring = Circle(center=(0, 0), radius=76, construction=true)
            low_ring = Circle(center=(0, 0), radius=84, construction=true)
            top = Text("CORE ROLLER", along=top_ring, size=8, font="sans:Bold", fill=true)
            low = Text("ANA 2026", along=low_ring, size=8, flip=true, font="sans:Bold", fill=true)
        }
    }
}

assembly ab_wheel {
    left_disc = disc()
    middle_disc = disc(d=168 mm)
    right_disc = disc(words=true)
    solid spacer_l {
        thickness 6 mm
        w = washer(outer=45 mm, inner=bore_d)
    }
    solid spacer_r {
        thickness 6 mm
        w = washer(outer=45 mm, inner=bore_d)
    }

    # the axle along x, 90 mm above the floor; each disc's top face looks right (+x)
    Place(left_disc, position=(0, 0, 90), face="right", up="up")
    Place(middle_disc, position=(ply, 0, 90), face="right", up="up")
    Place(right_disc, position=(2 * ply, 0, 90), face="right", up="up")
    Place(spacer_l, position=(-6, 0, 90), face="right", up="up")
    Place(spacer_r, position=(3 * ply, 0, 90), face="right", up="up")

    # flat on the sheet: discs in a row, spacers above the first
    RightOf(middle_disc, left_disc, gap=5)
    AlignBottom(middle_disc, left_disc)
    RightOf(right_disc, middle_disc, gap=5)
    AlignBottom(right_disc, middle_disc)
    Above(spacer_l, left_disc, gap=5)
    AlignLeft(spacer_l, left_disc)
    RightOf(spacer_r, spacer_l, gap=5)
    AlignBottom(spacer_r, spacer_l)

    assert left_disc.rim.diameter == 180 mm and right_disc.rim.diameter == 180 mm
    assert (left_disc.rim.diameter - middle_disc.rim.diameter) / 2 == 6 mm, "6 mm tyre channel"
    assert left_disc.bore.c.diameter == 20.5 mm
    assert len(left_disc.lights) == 6
    assert left_disc.light.c.diameter == 32 mm
    assert distance(left_disc.light.c.center, left_disc.rim.center) == 55 mm
    assert len(left_disc.pin) == 3
    assert distance(left_disc.pin[0].c.center, left_disc.rim.center) == 30 mm
    assert right_disc.rim_text.top.size == 8 mm and right_disc.rim_text.low.size == 8 mm
    assert spacer_l.w.ring.diameter == 45 mm and spacer_l.w.bore.b.diameter == 20.5 mm
    # the engraving clears the lightening holes and the rim
    assert distance(right_disc.rim_text, right_disc.lights) >= 2 mm
    assert right_disc.rim_text.bb.top <= right_disc.rim.bb.top - 3 mm
}
