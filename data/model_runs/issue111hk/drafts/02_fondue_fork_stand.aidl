# Request (kitchen): a stand for the 8 forks of our fondue set, so they stand upright round the
# table and nobody mixes up their fork. 6 mm birch ply, four parts: a 140 mm top disc with 8
# fork holes 9 mm across on a 110 mm circle (set between the column's arms, 22.5 deg off
# them), each hole numbered 1 to 8 just outside it (6 mm engraved numbers); a 140 mm base
# disc the tines rest on; between them a column of two 80 mm wide uprights, 120 mm between
# the discs, crossed by a halving joint and glued into the discs with two 15 mm tenons at each
# end. Slots and halvings with 0.1 mm clearance.

import "std/joints.aidl"

units mm
thickness 6 mm

param t = 6 mm, min = 3, max = 9
param disc_d = 140 mm, min = 120, max = 180
param gap_h = 120 mm, min = 80, max = 160     # between the discs
param up_w = 80 mm, min = 60, max = 100
param fit = 0.1 mm, min = 0, max = 0.3

pitch_r = 55 mm
hole_d = 9 mm
up_h = gap_h + 2 * t                          # tenon tip to tenon tip

def mortises(rot=0 deg) -> hole {
    j = tab_and_slot(part="slot", length=up_w, thickness=t, tabs=2, tab=15 mm, screw=0,
                     clearance=fit, rotation=rot)
}

def upright(from_top=true) -> solid {
    body = Rectangle(center=(0, 0), width=up_w, height=up_h)
    top_tabs = tab_and_slot(part="tab", length=up_w, thickness=t, tabs=2, tab=15 mm, screw=0,
                            cx=0 mm, cy=up_h / 2)
    bottom_tabs = tab_and_slot(part="tab", length=up_w, thickness=t, tabs=2, tab=15 mm,
                               screw=0, rotation=180 deg, cx=0 mm, cy=-up_h / 2)
    if from_top {
        halving = cross_halving(depth=up_h / 2, thickness=t, clearance=fit, cx=0 mm, cy=up_h / 2)
    } else {
        halving = cross_halving(depth=up_h / 2, thickness=t, clearance=fit, rotation=180 deg,
                                cx=0 mm, cy=-up_h / 2)
    }
}

assembly fondue_stand {
    solid top {
        disc = Circle(center=(0, 0), diameter=disc_d)
        hole forks {
            for i in range(8) {
                c = Circle(center=(pitch_r * cos(22.5 deg + i * 45 deg),
                                   pitch_r * sin(22.5 deg + i * 45 deg)), diameter=hole_d)
            }
        }
        m_x = mortises(rot=0 deg)
        m_y = mortises(rot=90 deg)
        # FIX after the first valid program: the numbers stood with their up away from the
        # centre, upside down for the person whose fork it is (the 6 read as a 9); flip=true
        # turns their up toward the centre, read from outside the disc.
        drawing numbers {
            ring = Circle(center=(0, 0), radius=pitch_r + hole_d / 2 + 2 mm + 6 mm, construction=true)
            for i in range(8) {
                n = Text(str(i + 1), along=ring, angle=22.5 deg + i * 45 deg, size=6, flip=true)
            }
        }
    }

    solid base {
        disc = Circle(center=(0, 0), diameter=disc_d)
        m_x = mortises(rot=0 deg)
        m_y = mortises(rot=90 deg)
    }

    a = upright(from_top=true)
    b = upright(from_top=false)

    # on the sheet: side by side
    RightOf(top, base, gap=10)
    AlignCenterY(top, base)
    RightOf(a, top, gap=10)
    AlignCenterY(a, base)
    RightOf(b, a, gap=10)
    AlignCenterY(b, base)

    # in 3D: base on the table, the uprights' bottom tenons through it, the top on their top tenons
    Place(base, position=(0, 0, 0))
    Place(top, position=(0, 0, t + gap_h))
    Place(a, position=(0, t / 2, up_h / 2), face="front", up="up")
    Place(b, position=(t / 2, 0, up_h / 2), face="left", up="up")
}

assert len(fondue_stand.top.forks.c) == 8, "8 fork holes"
assert abs(fondue_stand.top.disc.diameter - 140 mm) < 0.01 mm, "140 mm top disc"
assert abs(fondue_stand.base.disc.diameter - 140 mm) < 0.01 mm, "140 mm base disc"
assert abs(distance(fondue_stand.top.forks.c[0].center, fondue_stand.top.disc.center) - 55 mm) < 0.01 mm,
    "fork holes on a 110 mm circle"
assert abs(fondue_stand.a.body.width - 80 mm) < 0.01 mm, "80 mm wide uprights"
assert abs(fondue_stand.a.body.height - 2 * 6 mm - 120 mm) < 0.01 mm, "120 mm between the discs"
assert distance(fondue_stand.top.forks, fondue_stand.top.m_x) >= 5 mm, "fork holes clear of the mortises"
assert distance(fondue_stand.top.forks, fondue_stand.top.m_y) >= 5 mm, "fork holes clear of the mortises"
assert fondue_stand.top.numbers.bb.width < 140 mm - 2 mm, "numbers stay on the disc"
