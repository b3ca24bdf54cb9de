# Request: a paddle water wheel for the science club's hydro-power demo, all 3 mm ply.
# - Wheel: two 160 mm side discs, 60 mm apart inside, on a 6 mm steel axle (6 mm hole, a
#   press fit), each with six 18 mm lightening holes on a 28 mm radius and twelve mortises
#   for the paddles; twelve radial paddles 60 x 35 mm between the discs, reaching from 45 mm
#   to the rim (80 mm), each with a 15 mm wide tenon at both ends through the discs
#   (mortises 0.2 mm oversize).
# - Stand: two uprights with a round top (30 mm across) and a 100 mm wide foot, the axle's
#   6.5 mm bearing hole 100 mm above the base's underside, standing 7 mm outside the discs;
#   each has two 20 mm tabs glued into mortises of the base, a 130 x 200 mm plate with 8 mm
#   corner radii, "WATER WHEEL" engraved 8 mm tall and "SCIENCE CLUB 2026" 5 mm tall near
#   its front edge.
# The wheel turns clear of the base.
# FIX after the first valid program: on the flat drawing the base (200 mm tall) reached up
# into the first row of paddles (W0511); the paddle rows now start above the base.

import "std/joints.aidl"

t = 6 mm / 2
thickness t

disc_r = 80 mm
inner_w = 60 mm
pad_in = 45 mm
pad_d = disc_r - pad_in
pad_mid = (pad_in + disc_r) / 2
axle_h = 100 mm
upright_x = inner_w / 2 + t + 7 mm

def side_disc() -> solid {
    disc = Circle(center=(0, 0), radius=disc_r)
    hole axle { c = Circle(center=(0, 0), diameter=6 mm) }
    for k in range(6) {
        hole light { c = Circle(center=polar((0, 0), 28 mm, 30 deg + k * 60 deg), diameter=18 mm) }
    }
    for k in range(12) {
        mortise = tab_and_slot(part="slot", length=pad_d, thickness=t, tabs=1, tab=15 mm, screw=0,
                               clearance=0.2 mm, rotation=k * 30 deg,
                               cx=pad_mid * cos(k * 30 deg), cy=pad_mid * sin(k * 30 deg))
    }
}

def paddle() -> solid {
    body = Rectangle(center=(0, pad_mid), width=inner_w + 2 * t, height=pad_d)
    right_tenon = tab_and_slot(part="tab", length=pad_d, thickness=t, tabs=1, tab=15 mm, screw=0,
                               rotation=-90 deg, cx=inner_w / 2 + t, cy=pad_mid)
    left_tenon = tab_and_slot(part="tab", length=pad_d, thickness=t, tabs=1, tab=15 mm, screw=0,
                              rotation=90 deg, cx=-inner_w / 2 - t, cy=pad_mid)
}

def upright() -> solid {
    body = Hull(Circle(center=(0, axle_h), radius=15 mm), Point(-50 mm, 0), Point(50 mm, 0))
    hole bearing { c = Circle(center=(0, axle_h), diameter=6.5 mm) }
    feet = tab_and_slot(part="tab", length=100 mm, thickness=t, tabs=2, tab=20 mm, screw=0,
                        rotation=180 deg, cx=0, cy=0)
}

assembly water_wheel {
    left_disc = side_disc()
    right_disc = side_disc()
    for k in range(12) { pad = paddle() }
    left_post = upright()
    right_post = upright()
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=130 mm, height=200 mm, corner_radius=8 mm)
        left_slots = tab_and_slot(part="slot", length=100 mm, thickness=t, tabs=2, tab=20 mm,
                                  screw=0, clearance=0.2 mm, rotation=90 deg, cx=-upright_x - t / 2, cy=0)
        right_slots = tab_and_slot(part="slot", length=100 mm, thickness=t, tabs=2, tab=20 mm,
                                   screw=0, clearance=0.2 mm, rotation=90 deg, cx=upright_x + t / 2, cy=0)
        drawing label {
            name = Text("WATER WHEEL", position=(0, -78 mm), size=8)
            club = Text("SCIENCE CLUB 2026", position=(0, -91 mm), size=5)
        }
    }

    # flat layout
    RightOf(right_disc, left_disc, gap=6)
    AlignBottom(right_disc, left_disc)
    RightOf(base, right_disc, gap=6)
    AlignBottom(base, left_disc)
    RightOf(left_post, base, gap=6)
    AlignBottom(left_post, base)
    Above(right_post, left_post, gap=6)
    AlignLeft(right_post, left_post)
    Above(pad[0], base, gap=6)
    AlignLeft(pad[0], left_disc)
    Above(pad[6], pad[0], gap=6)
    AlignLeft(pad[6], pad[0])
    for k in range(1, 12) {
        if k != 6 {
            RightOf(pad[k], pad[k - 1], gap=6)
            AlignBottom(pad[k], pad[k - 1])
        }
    }

    # assembled: axle along x, 100 mm up
    Place(base, position=(0, 0, 0), face="up")
    Place(left_post, position=(-upright_x, 0, 0), face="left", up="up")
    Place(right_post, position=(upright_x, 0, 0), face="right", up="up")
    Place(left_disc, position=(-inner_w / 2, 0, axle_h), face="left", up="up")
    Place(right_disc, position=(inner_w / 2, 0, axle_h), face="right", up="up")
    for k in range(12) {
        Place(pad[k], position=(0, t / 2 * sin(k * 30 deg), axle_h - t / 2 * cos(k * 30 deg)),
              rotation=(k * 30 deg, 0, 0))
    }

    assert left_disc.disc.diameter == 160 mm, "160 mm discs"
    assert left_disc.axle.c.diameter == 6 mm and left_post.bearing.c.diameter == 6.5 mm, "axle holes"
    assert len(left_disc.light) == 6 and left_disc.light[0].c.diameter == 18 mm, "six 18 mm holes"
    assert distance(left_disc.light[0].c.center, left_disc.disc.center) == 28 mm, "on a 28 mm radius"
    assert len(pad) == 12 and len(left_disc.mortise) == 12, "twelve paddles, twelve mortises"
    assert pad[0].body.width == 60 mm + 2 * 3 mm, "60 mm between the discs plus two tenons"
    assert pad[0].body.height == 35 mm, "35 mm paddles"
    assert pad[0].body.bb.top - pad[0].body.bb.bottom == 80 mm - 45 mm, "from 45 mm to the rim"
    assert left_disc.mortise[0].slot[0].bb.width == 15.2 mm, "mortise 0.2 oversize along"
    assert left_disc.mortise[0].slot[0].bb.height == 3.2 mm, "mortise 0.2 oversize across"
    assert distance(left_disc.mortise[0].slot[0].bb.center, left_disc.disc.center) == pad_mid, "mortise at the tenon"
    assert left_post.bearing.c.center.y - left_post.body.bb.bottom == 100 mm, "axle 100 mm up"
    assert left_post.body.bb.width == 100 mm, "100 mm foot"
    assert upright_x - (inner_w / 2 + t) == 7 mm, "posts 7 mm outside the discs"
    assert base.plate.width == 130 mm and base.plate.height == 200 mm, "130 x 200 base"
    assert axle_h - disc_r - t >= 10 mm, "the wheel clears the base"
    assert base.label.name.size == 8 mm and base.label.club.size == 5 mm, "label sizes"
    assert distance(base.label, base.left_slots) >= 5 mm, "label clear of the slots"
}
