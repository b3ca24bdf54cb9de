# Request (garden): a flat-pack tomato support for a big patio pot, 6 mm exterior ply.
# Three legs 600 mm long (a 40 mm wide strip with a round top and a 60 mm spike at the
# bottom to push into the soil) stand radially, their inner edges 125 mm from the pot's
# centre, at 30, 150 and 270 degrees. Two rings (300 mm outside, 240 mm inside) slot onto
# the legs by cross-halvings (ring slots 15 deep from the outside, leg notches 10 deep from
# the inner edge) 200 mm and 450 mm above the soil line (the top of the spike). Each leg has
# five 5 mm holes 100 mm apart for tying the stem, the first 100 mm above the soil line,
# 30 mm from the leg's inner edge. The upper ring is engraved "TOMATOES", the lower
# "SAN MARZANO", filled bold 10 mm letters along the middle of the ring, centred at the top.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
legs_at = [30 deg, 150 deg, 270 deg]
r_in = 125 mm     # the legs' inner edges from the centre
soil = 60 mm      # the spike's length: the soil line above the tip
z1 = 200 mm
z2 = 450 mm

def leg_part() -> solid {
    body = RoundedRectangle(bottom_left=(0, 0), width=40, height=540,
                            corner_radii=[20, 20, 0, 0])
    spike = Polygon([(0, 0), (40, 0), (20, -60)])
    n1 = cross_halving(depth=10 mm, thickness=t, rotation=90 deg, cx=0 mm, cy=z1)
    n2 = cross_halving(depth=10 mm, thickness=t, rotation=90 deg, cx=0 mm, cy=z2)
    hole tie {
        c = Circle(center=(30, 100), diameter=5)
    }
    ties = LinearPattern(tie, 5, (0, 100))
}

def ring_part(word="TOMATOES") -> solid {
    outer = Circle(center=(0, 0), diameter=300)
    hole inner {
        c = Circle(center=(0, 0), diameter=240)
    }
    for a in legs_at {
        s = cross_halving(depth=15 mm, thickness=t, rotation=a - 90 deg,
                          cx=150 mm * cos(a), cy=150 mm * sin(a))
    }
    drawing label {
        path = Circle(center=(0, 0), radius=135, construction=true)
        w = Text(word, along=path, size=10, valign="middle", font="sans:Bold", fill=true)
    }
}

assembly cage {
    for i in range(3) {
        leg = leg_part()
        Place(leg, position=(r_in * cos(legs_at[i]) - t / 2 * sin(legs_at[i]),
                             r_in * sin(legs_at[i]) + t / 2 * cos(legs_at[i]), soil),
              face=(sin(legs_at[i]), -cos(legs_at[i]), 0), up="up")
    }
    lower = ring_part(word="SAN MARZANO")
    upper = ring_part(word="TOMATOES")
    Place(lower, position=(0, 0, soil + z1 - t / 2), face="up")
    Place(upper, position=(0, 0, soil + z2 - t / 2), face="up")

    # flat on the sheet
    RightOf(leg[1], leg[0], gap=8)
    RightOf(leg[2], leg[1], gap=8)
    AlignBottom(leg[1], leg[0])
    AlignBottom(leg[2], leg[0])
    RightOf(lower, leg[2], gap=10)
    AlignBottom(lower, leg[0])
    Above(upper, lower, gap=10)
    AlignLeft(upper, lower)

    assert len(leg) == 3, "three legs"
    assert leg[0].bb.height == 600 mm, "legs 600 long"
    assert leg[0].body.bb.bottom - leg[0].spike.bb.bottom == 60 mm, "60 mm spike"
    assert lower.outer.diameter == 300 mm and lower.inner.c.diameter == 240 mm, "rings 300 / 240"
    assert leg[0].n1.cut.bb.center_y - leg[0].body.bb.bottom == 200 mm, "lower ring 200 above soil"
    assert leg[0].n2.cut.bb.center_y - leg[0].body.bb.bottom == 450 mm, "upper ring 450 above soil"
    assert leg[0].ties[0].c.center.y - leg[0].body.bb.bottom == 100 mm, "first tie 100 above soil"
    assert leg[0].ties[1].c.center.y - leg[0].ties[0].c.center.y == 100 mm, "ties 100 apart"
    assert len(leg[0].ties) == 5, "five ties"
    # the halvings meet: leg notch bottom and ring slot bottom at the same radius
    assert r_in + 10 mm == 150 mm - 15 mm, "notch depths add up to the overlap"
}
