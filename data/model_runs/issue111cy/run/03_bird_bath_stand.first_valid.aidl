# Request (garden): a slot-together stand for a bird bath made from a 300 mm plastic plant
# saucer, 6 mm exterior ply. Two identical-looking legs 500 mm tall cross at right angles
# (an X seen from above), joined by a cross-halving, 0.2 mm clearance: one leg slotted from
# the top, the other from the bottom, 250 mm each. Each leg has a curved, vase-like outline:
# a 300 mm wide foot, 12 mm high at its ends, narrowing to a 90 mm waist at 260 mm up and
# flaring to 316 mm across the top. A 330 mm top disc sits on the legs, each leg glued into
# it with 2 tabs 25 mm wide; a ring, 330 mm outside and 305 mm inside, is glued on the disc
# so the saucer cannot slide off.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
H = 500 mm
fit = 0.2 mm

def leg(from_top=true) -> solid {
    half = [(0, 0), (150, 0), (150, 12), (110, 40), (60, 150), (45, 260), (70, 380),
            (130, 460), (158, 500), (0, 500)]
    outline = Spline(mirror(half, about="y"), closed=true, corners=[1, 2, 8, 10, 16, 17])
    top_tabs = tab_and_slot(part="tab", length=316 mm, thickness=T, tabs=2, tab=25 mm,
                            screw=0, cx=0 mm, cy=H)
    if from_top {
        halving = cross_halving(depth=H / 2, thickness=T, clearance=fit, cx=0 mm, cy=H)
    } else {
        halving = cross_halving(depth=H / 2, thickness=T, clearance=fit, rotation=180 deg,
                                cx=0 mm, cy=0 mm)
    }
}

assembly bird_bath {
    leg_a = leg(from_top=true)
    leg_b = leg(from_top=false)

    solid disc {
        plate = Circle(center=(0, 0), diameter=330 mm)
        mortise_a = tab_and_slot(part="slot", length=316 mm, thickness=T, tabs=2, tab=25 mm,
                                 screw=0, cx=0 mm, cy=0 mm)
        mortise_b = tab_and_slot(part="slot", length=316 mm, thickness=T, tabs=2, tab=25 mm,
                                 screw=0, rotation=90 deg, cx=0 mm, cy=0 mm)
    }

    solid ring {
        rim = Circle(center=(0, 0), diameter=330 mm)
        hole inside {
            c = Circle(center=(0, 0), diameter=305 mm)
        }
    }

    # flat for cutting
    RightOf(leg_b, leg_a, gap=10 mm)
    AlignBottom(leg_b, leg_a)
    RightOf(disc, leg_b, gap=10 mm)
    AlignBottom(disc, leg_a)
    RightOf(ring, disc, gap=10 mm)
    AlignBottom(ring, leg_a)

    # assembled: leg_a in the x-z plane, leg_b in the y-z plane, the disc on top
    Place(leg_a, position=(0, T / 2, 0), face="front", up="up")
    Place(leg_b, position=(-T / 2, 0, 0), face="right", up="up")
    Place(disc, position=(0, 0, H - T), face="up", up="back")
    Place(ring, position=(0, 0, H), face="up", up="back")

    # the request's numbers
    assert leg_a.outline.bb.height == 500 mm, "legs 500 mm tall"
    assert leg_a.halving.depth + leg_b.halving.depth == 500 mm, "halvings meet: 250 + 250"
    assert leg_a.halving.depth == 250 mm, "250 mm each"
    assert leg_a.outline.points[1].x - leg_a.outline.points[17].x == 300 mm, "300 mm foot"
    assert leg_a.outline.points[2].y == 12 mm, "foot 12 mm high at its ends"
    assert leg_a.outline.points[5].x * 2 == 90 mm and leg_a.outline.points[5].y == 260 mm,
        "90 mm waist at 260 mm"
    assert leg_a.outline.points[8].x - leg_a.outline.points[10].x == 316 mm, "316 mm top"
    assert disc.plate.diameter == 330 mm, "330 mm disc"
    assert ring.rim.diameter == 330 mm and ring.inside.c.diameter == 305 mm, "ring 330 / 305"
    assert ring.inside.c.diameter > 300 mm, "the saucer drops in"
    assert len(disc.mortise_a.slot) == 2 and len(disc.mortise_b.slot) == 2, "2 tabs a leg"
}
