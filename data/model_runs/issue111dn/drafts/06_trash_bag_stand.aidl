# Request: a flat-pack bin-bag stand for the campsite, 6 mm exterior ply. A 30-litre bag
# hangs inside a top ring (360 mm across, 250 mm opening) with its mouth folded over the
# ring. Four legs stand outside the bag, at 45, 135, 225 and 315 degrees: each leg is 450 mm
# tall to the ring's top, its inner edge straight up at 130 mm from the centre (5 mm clear
# of the bag), 40 mm wide (out to 170 mm) and flaring out to 200 mm at the foot over the
# lowest 120 mm. Each leg's top has one 20 mm tab through a mortise in the top ring. A
# brace ring (360 across, 250 opening) 150 mm up holds the legs apart: it and each leg are
# cross-halved (the leg slotted 20 mm in from its inner edge, the ring 30 mm in from its
# outer edge). "PACK IT IN" is engraved 10 mm high along the top ring over the top and
# "PACK IT OUT" readable under the bottom.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
ring_d = 360 mm
bag_d = 250 mm
H = 450 mm
r_leg = 130 mm
leg_w = 40 mm
foot = 200 mm
flare = 120 mm
brace_z = 150 mm
angles = [45 deg, 135 deg, 225 deg, 315 deg]

def leg_panel() -> solid {
    # x: the distance from the stand's axis; y: the height above the ground
    body = Polygon([(r_leg, 0), (foot, 0), (r_leg + leg_w, flare), (r_leg + leg_w, H),
                    (r_leg, H)])
    top = tab_and_slot(part="tab", length=leg_w, thickness=t, tabs=1, tab=20 mm, screw=0,
                       cx=r_leg + leg_w / 2, cy=H)
    brace = cross_halving(depth=20 mm, thickness=t, rotation=90 deg, cx=r_leg,
                          cy=brace_z + t / 2)
}

assembly stand {
    solid top_ring {
        body = Circle(center=(0, 0), diameter=ring_d)
        Fixed(body)
        hole mouth { c = Circle(center=(0, 0), diameter=bag_d) }
        for a in angles {
            m = tab_and_slot(part="slot", length=leg_w, thickness=t, tabs=1, tab=20 mm,
                             screw=0, rotation=a, cx=(r_leg + leg_w / 2) * cos(a),
                             cy=(r_leg + leg_w / 2) * sin(a))
        }
        drawing words {
            mid = Circle(center=(0, 0), radius=(ring_d + bag_d) / 4, construction=true)
            over = Text("PACK IT IN", along=mid, size=10, valign="middle")
            under = Text("PACK IT OUT", along=mid, size=10, valign="middle", flip=true)
        }
    }

    solid brace_ring {
        body = Circle(center=(0, 0), diameter=ring_d)
        Fixed(body)
        hole mouth { c = Circle(center=(0, 0), diameter=bag_d) }
        for a in angles {
            h = cross_halving(depth=30 mm, thickness=t, rotation=a - 90 deg,
                              cx=ring_d / 2 * cos(a), cy=ring_d / 2 * sin(a))
        }
    }

    for i in range(4) {
        leg = leg_panel()
        # assembled: the panel in the vertical plane through its angle, x outward
        Place(leg, position=(-t / 2 * sin(angles[i]), t / 2 * cos(angles[i]), 0),
              face=(sin(angles[i]), -cos(angles[i]), 0), up="up")
    }

    # flat: the rings side by side, the legs in a row beside them
    RightOf(brace_ring, top_ring, gap=10)
    AlignCenterY(brace_ring, top_ring)
    RightOf(leg[0], brace_ring, gap=10)
    AlignBottom(leg[0], brace_ring)
    for i in range(1, 4) {
        RightOf(leg[i], leg[i - 1], gap=10)
        AlignBottom(leg[i], leg[i - 1])
    }

    Place(top_ring, position=(0, 0, H - t), face="up")
    Place(brace_ring, position=(0, 0, brace_z), face="up")

    assert len(leg) == 4
    assert leg[0].body.bb.height == 450 mm, "450 mm to the ring's top"
    assert top_ring.body.diameter == 360 mm and top_ring.mouth.c.diameter == 250 mm
    assert r_leg - bag_d / 2 == 5 mm, "legs 5 mm clear of the bag"
    assert leg[0].body.bb.right - leg[0].body.bb.left == 70 mm, "foot out to 200 mm"
    assert leg[0].brace.depth + brace_ring.h[0].depth == 50 mm, "halvings cover 130..180"
}
