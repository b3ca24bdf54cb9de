# Request (gifts): a layered trinket dish for rings and earrings, 3 mm ply, glued as a stack of
# four. Every layer has the same scalloped flower outline: a 90 mm disc with eight round
# scallops (R13, their centres on a 44 mm radius, 45 degrees apart) so it is 114 mm across,
# the inner corners rounded R3. The base is whole; the three rings above it have round
# openings of 60, 68 and 76 mm (bottom to top), so the walls step outward. Two 3 mm holes for
# alignment pins go through every layer, in the scallops at 0 and 180 degrees, 49 mm from the
# centre. The base carries the initial "E" (bold serif, 26 mm capital, engraved filled) in a
# 54 mm engraved circle, centred.

thickness 3 mm

disc_d = 90 mm
bump_r = 13 mm
bump_at = 44 mm
bumps = 8
pin_d = 3 mm
pin_at = 49 mm
bores = [60 mm, 68 mm, 76 mm]

def layer(bore=0 mm) -> solid {
    disc = Circle(center=(0, 0), diameter=disc_d)
    for i in range(bumps) {
        bump = Circle(center=(bump_at * cos(i * 360 deg / bumps),
                              bump_at * sin(i * 360 deg / bumps)), radius=bump_r)
    }
    if bore > 0 mm {
        hole well { c = Circle(center=(0, 0), diameter=bore) }
    }
    hole pins {
        a = Circle(center=(pin_at, 0), diameter=pin_d)
        b = Circle(center=(-pin_at, 0), diameter=pin_d)
    }
    Fillet(3 mm)
}

assembly trinket_dish {
    solid base {
        plate = layer()
        drawing mono {
            ring = Circle(center=(0, 0), diameter=54)
            letter = Text("E", position=(0, 0), size=26, font="serif:Bold",
                          valign="middle", fill=true)
        }
    }
    ring1 = layer(bore=bores[0])
    ring2 = layer(bore=bores[1])
    ring3 = layer(bore=bores[2])

    # flat: in a row
    RightOf(ring1, base, gap=8)
    AlignCenterY(ring1, base)
    RightOf(ring2, ring1, gap=8)
    AlignCenterY(ring2, base)
    RightOf(ring3, ring2, gap=8)
    AlignCenterY(ring3, base)

    # 3D: stacked, base at the bottom
    Place(base, position=(0, 0, 0), face="up")
    Place(ring1, position=(0, 0, 3 mm), face="up")
    Place(ring2, position=(0, 0, 6 mm), face="up")
    Place(ring3, position=(0, 0, 9 mm), face="up")

    assert base.bb.width == 114 mm, "114 across"
    assert len(ring1.bump) == 8, "eight scallops"
    assert ring1.well.c.diameter == 60 mm and ring2.well.c.diameter == 68 mm and
        ring3.well.c.diameter == 76 mm, "openings 60 / 68 / 76"
    assert disc_d / 2 - ring3.well.c.radius >= 6 mm, "rim at least 6 at the valleys"
    assert ring3.pins.a.center.x - ring3.disc.center.x == 49 mm, "pins 49 out"
    assert distance(ring3.pins, ring3.well) >= 5 mm, "pins clear of the opening"
    assert base.mono.letter.size == 26 mm, "26 mm initial"
    assert base.mono.ring.diameter == 54 mm, "54 mm circle"
    assert base.mono.ring.diameter <= bores[0] - 4 mm, "circle seen through the first opening"
}
