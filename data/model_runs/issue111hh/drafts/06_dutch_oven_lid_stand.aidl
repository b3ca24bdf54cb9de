# Request (camping): a flat-pack lid stand for a 12-inch camp Dutch oven, laser-cut from
# 3 mm mild steel, so the hot lid can be set down off the ground.
# - A top ring 180 mm across the outside and 130 mm inside, with three radial slots at 120
#   degrees (at 30, 150 and 270 degrees), each for one 15 mm tab of a leg, centred in the
#   ring's band. "CAMP KITCHEN" engraved on the ring in 6 mm letters, centred at the top
#   (90 degrees), following the ring.
# - Three identical legs standing radially under the slots: trapezoids 100 mm tall to the
#   shoulder, 90 mm wide at the floor and 30 mm under the ring, one 15 mm tab in the middle of
#   the top edge up through the ring, the floor corners rounded 3 mm and a 30 mm lightening
#   hole 45 mm above the floor.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
r_out = 90 mm
r_in = 65 mm
r_mid = (r_out + r_in) / 2
leg_h = 100 mm

def leg() -> solid {
    body = Trapezoid(center=(0, (leg_h + t) / 2), bottom_width=90, top_width=30, height=leg_h + t)
    top_tab = tab_and_slot(part="tab", length=30, thickness=t, tabs=1, tab=15, screw=0,
                           cx=0, cy=leg_h + t)
    hole lighten {
        c = Circle(center=(0, 45), diameter=30)
    }
    Fillet([body.bottom_left, body.bottom_right], 3)
}

assembly lid_stand {
    solid ring {
        outer = Circle(center=(0, 0), radius=r_out)
        hole bore {
            c = Circle(center=(0, 0), radius=r_in)
        }
        for i in range(3) {
            leg_slot = tab_and_slot(part="slot", length=30, thickness=t, tabs=1, tab=15, screw=0,
                                    rotation=30 deg + i * 120 deg,
                                    cx=r_mid * cos(30 deg + i * 120 deg),
                                    cy=r_mid * sin(30 deg + i * 120 deg))
        }
        drawing label {
            path = Circle(center=(0, 0), radius=r_mid, construction=true)
            words = Text("CAMP KITCHEN", along=path, angle=90 deg, size=6, valign="middle")
        }
    }

    for j in range(3) {
        legs = leg()
    }

    RightOf(legs[0], ring, gap=10)
    AlignBottom(legs[0], ring)
    RightOf(legs[1], legs[0], gap=10)
    AlignBottom(legs[1], legs[0])
    RightOf(legs[2], legs[1], gap=10)
    AlignBottom(legs[2], legs[1])

    assert ring.outer.diameter == 180 mm and ring.bore.c.diameter == 130 mm
    assert len(ring.leg_slot) == 3 and len(legs) == 3
    assert distance(ring.leg_slot[0].slot[0].center, ring.outer.center) == r_mid
    assert distance(ring.label, ring.leg_slot) >= 3 mm
    assert distance(ring.label, ring.bore) >= 2 mm
    assert legs[0].body.height == 103 mm and legs[0].body.bottom_width == 90 mm
    assert legs[0].lighten.c.center.y - legs[0].body.bb.bottom == 45 mm
}
