# Request (parties): a base for a balloon column at my daughter's 30th, for a 20 mm pole,
# in 3 mm ply. The base plate is a 280 mm disc with 24 R14 scallops round its rim. Four
# radial fins stand on it 90 degrees apart, each from 20 mm to 100 mm out from the centre,
# 80 tall at the inside for the first 35 mm, then sloping down to 20 tall at the outer end,
# each glued into the base with two 15 mm tenons. On the fins sits a 120 mm collar disc with
# a 20.5 mm hole for the pole, held by one 15 mm tenon from each fin. A 36 mm washer with a
# 20.5 mm hole is glued on the base's centre to locate the pole's foot. Four 6 mm holes for
# tent pegs, 128 mm out on the diagonals (between the fins). Engraved filled round the base
# (sans bold, 14 mm caps): HAPPY 30TH over the top, on a 122 mm radius, and SAM under the
# bottom, the right way up.

import "std/joints.aidl"
import "std/shapes.aidl"

thickness 3 mm

t = 3 mm
pole_hole = 20.5 mm
fin_in = 20 mm
fin_out = 100 mm
fin_h = 80 mm
flat = 35 mm
fin_end_h = 20 mm
collar_d = 120 mm
text_r = 122 mm

def fin() -> solid {
    # drawn radially: x outward from the pole's axis, y up from the base's top face
    body = Polygon([(fin_in, -t), (fin_out, -t), (fin_out, fin_end_h), (fin_in + flat, fin_h),
                    (fin_in + flat, fin_h + t), (fin_in, fin_h + t)])
    feet = tab_and_slot(part="tab", length=fin_out - fin_in, thickness=t, tabs=2, tab=15 mm,
                        screw=0, rotation=180 deg, cx=(fin_in + fin_out) / 2, cy=-t)
    top = tab_and_slot(part="tab", length=flat, thickness=t, tabs=1, tab=15 mm, screw=0,
                       cx=fin_in + flat / 2, cy=fin_h + t)
}

assembly balloon_base {
    solid base {
        disc = Circle(center=(0, 0), diameter=280)
        bump = Circle(center=(140, 0), radius=14)
        bumps = CircularPattern(bump, 24, (0, 0))
        for k in range(4) {
            m = tab_and_slot(part="slot", length=fin_out - fin_in, thickness=t, tabs=2,
                             tab=15 mm, screw=0, rotation=k * 90 deg,
                             cx=(fin_in + fin_out) / 2 * cos(k * 90 deg),
                             cy=(fin_in + fin_out) / 2 * sin(k * 90 deg))
        }
        hole pegs {
            for k in range(4) {
                p = Circle(center=(128 * cos(45 deg + k * 90 deg), 128 * sin(45 deg + k * 90 deg)),
                           diameter=6)
            }
        }
        drawing words {
            ring = Circle(center=(0, 0), radius=text_r, construction=true)
            top = Text("HAPPY 30TH", along=ring, size=14, font="sans:Bold", fill=true)
            bottom = Text("SAM", along=ring, size=14, font="sans:Bold", fill=true, flip=true)
        }
    }

    solid collar {
        disc = Circle(center=(0, 0), diameter=collar_d)
        hole pole { c = Circle(center=(0, 0), diameter=pole_hole) }
        for k in range(4) {
            m = tab_and_slot(part="slot", length=flat, thickness=t, tabs=1, tab=15 mm, screw=0,
                             rotation=k * 90 deg,
                             cx=(fin_in + flat / 2) * cos(k * 90 deg),
                             cy=(fin_in + flat / 2) * sin(k * 90 deg))
        }
    }

    foot = washer(outer=36 mm, inner=pole_hole)

    for k in range(4) {
        f = fin()
    }

    # assembled: the base on z = 0, the pole's axis on x = y = 0
    Place(base, position=(0, 0, 0), face="up")
    Place(foot, position=(0, 0, t), face="up")
    Place(collar, position=(0, 0, t + fin_h), face="up")
    faces = ["front", "right", "back", "left"]
    pos = [(0, t / 2, t), (-t / 2, 0, t), (0, -t / 2, t), (t / 2, 0, t)]
    for k in range(4) {
        Place(f[k], position=pos[k], face=faces[k], up="up")
    }

    # laid out flat
    RightOf(collar, base, gap=6)
    AlignTop(collar, base)
    RightOf(foot, collar, gap=6)
    AlignTop(foot, collar)
    Below(f[0], collar, gap=6)
    AlignLeft(f[0], collar)
    RightOf(f[1], f[0], gap=6)
    AlignTop(f[1], f[0])
    Below(f[2], f[0], gap=6)
    AlignLeft(f[2], f[0])
    RightOf(f[3], f[2], gap=6)
    AlignTop(f[3], f[2])

    # the request's numbers
    assert len(f) == 4, "four fins"
    assert base.disc.diameter == 280 mm and len(base.bumps) == 24, "280 disc, 24 scallops"
    assert f[0].body.bb.width == 80 mm, "fins 20 to 100 out"
    assert f[0].body.bb.height - 2 * t == 80 mm, "fins 80 tall"
    assert collar.pole.c.diameter == 20.5 mm and foot.bore.b.diameter == 20.5 mm, "pole holes"
    assert foot.ring.diameter == 36 mm, "36 mm foot washer"
    assert distance(base.words, base.m[0]) >= 3 mm, "words clear of the fins"
    assert distance(base.words, base.pegs) >= 3 mm, "words clear of the peg holes"
    assert distance(base.pegs.p[0].center, base.disc.center) == 128 mm, "pegs 128 out"
}
