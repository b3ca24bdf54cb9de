# Request (music): a cello endpin anchor (rock stop strap), two layers of 3 mm ply glued
# together. A tapered strap 420 mm long overall, 70 mm wide with a round end at the chair
# leg, 50 mm wide with a round end at the other: a 45 mm hole for the chair leg centred in
# the wide end; five endpin cups 8 mm across, 25 mm apart, the last centred in the narrow
# end, cut through the top layer only (the bottom layer closes them into 3 mm deep cups);
# each cup numbered 1..5 (5 mm) below it, the nearest the chair 1; "CELLO" engraved 10 mm
# tall between the chair hole and the cups. Two parts: top and bottom layer.

units mm
thickness 3 mm

param cups = 5, min = 3, max = 6
length = 420 mm
wide = 70 mm
narrow = 50 mm
leg_d = 45 mm
cup_d = 8 mm
cup_pitch = 25 mm
far = length - wide / 2 - narrow / 2

def layer(with_cups) -> solid {
    strap = Hull(Circle(center=(0, 0), diameter=wide), Circle(center=(far, 0), diameter=narrow))
    hole leg {
        c = Circle(center=(0, 0), diameter=leg_d)
    }
    if with_cups {
        for k in range(cups) {
            hole cup {
                c = Circle(center=(far - (cups - 1 - k) * cup_pitch, 0), diameter=cup_d)
            }
            drawing number {
                n = Text(str(k + 1), (far - (cups - 1 - k) * cup_pitch, -16), size=5)
            }
        }
        drawing name {
            word = Text("CELLO", ((leg_d / 2 + far - (cups - 1) * cup_pitch) / 2, 0), size=10,
                        valign="middle")
        }
    }
}

assembly anchor {
    top = layer(true)
    bottom = layer(false)
    Place(bottom, position=(0, 0, 0))
    Place(top, position=(0, 0, 3))
    Below(bottom, top, gap=5)

    assert top.strap.bb.width == 420 mm, "420 mm long"
    assert top.strap.bb.height == 70 mm, "70 mm at the chair end"
    assert len(top.cup) == 5, "five cups"
    assert top.cup[1].c.center.x - top.cup[0].c.center.x == 25 mm, "cups 25 mm apart"
    assert top.strap.bb.right - top.cup[4].c.center.x == 25 mm, "last cup centred in the 50 mm end"
}
