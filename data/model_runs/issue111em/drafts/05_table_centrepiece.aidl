# Request: a wedding table centrepiece, flat-pack in 3 mm birch ply, lit by four LED
# tealights. A round base 180 mm across with four 39.5 mm holes for the tealights (38 mm
# cups sitting on the table through them), their centres 58 mm from the middle on the
# diagonals, and "EMMA & TOM  16 JUNE 2027" engraved along the rim (5 mm letters). Two
# arched panels 150 mm wide, 200 mm tall above the base (a semicircular top of 75 mm
# radius), cross-halved at their middle (one slotted 100 mm from the top, the other 100
# mm from the bottom), each standing in the base on two 20 mm tabs glued into slots.
# Each panel is pierced with six hearts (about 26 mm wide) in two columns 45 mm either
# side of the middle, rows 30, 70 and 110 mm above the base. The panel slotted from the
# bottom also has the initials "E & T" cut through as a stencil (24 mm letters) in its
# arch, centred 150 mm above the base.

units mm
thickness 3 mm

import "std/joints.aidl"

panel_w = 150 mm
panel_h = 200 mm
arch_r = 75 mm

def panel(from_top=true) -> solid {
    lower = Rectangle(corner=(-panel_w / 2, -3), opposite=(panel_w / 2, panel_h - arch_r))
    arch = Circle(center=(0, panel_h - arch_r), radius=arch_r)
    feet = tab_and_slot(part="tab", length=panel_w, thickness=3, tabs=2, tab=20, screw=0,
                        rotation=180 deg, cx=0, cy=-3)
    if from_top {
        halve = cross_halving(depth=panel_h / 2, thickness=3, clearance=0.1, cx=0, cy=panel_h)
    } else {
        halve = cross_halving(depth=panel_h / 2, thickness=3, clearance=0.1, rotation=180 deg,
                              cx=0, cy=0)
        hole initials {
            t = Text("E & T", position=(0, 150), size=24, font="sans:Bold", stencil=true,
                     valign="middle")
        }
    }
    hole hearts {
        for i in range(6) {
            x = (i % 2 * 2 - 1) * 45
            y = 30 + i // 2 * 40
            left = Hull(Circle(center=(x - 6, y + 4), radius=7), Point(x, y - 12))
            right = Hull(Circle(center=(x + 6, y + 4), radius=7), Point(x, y - 12))
        }
    }
}

assembly centrepiece {
    solid base {
        disc = Circle(center=(0, 0), diameter=180)
        hole lights {
            for i in range(4) {
                c = Circle(center=polar((0, 0), 58, 45 deg + i * 90 deg), diameter=39.5)
            }
        }
        slots_a = tab_and_slot(part="slot", length=panel_w, thickness=3, tabs=2, tab=20,
                               screw=0, clearance=0.1, cx=0, cy=0)
        slots_b = tab_and_slot(part="slot", length=panel_w, thickness=3, tabs=2, tab=20,
                               screw=0, clearance=0.1, rotation=90 deg, cx=0, cy=0)
        drawing names {
            rim = Circle(center=(0, 0), radius=80, construction=true)
            t = Text("EMMA & TOM  16 JUNE 2027", along=rim, size=5)
        }
        Fixed(disc)
    }
    front = panel(from_top=true)
    cross = panel(from_top=false)

    RightOf(front, base, gap=5)
    AlignBottom(front, base)
    RightOf(cross, front, gap=5)
    AlignBottom(cross, base)

    Place(base, position=(0, 0, 0), face="up")
    Place(front, position=(0, 1.5, 3), face="front", up="up")
    Place(cross, position=(-1.5, 0, 3), face="right", up="up")

    # the request's numbers
    assert base.disc.diameter == 180 mm, "base 180 across"
    assert len(base.lights.c) == 4, "four tealights"
    assert base.lights.c[0].diameter == 39.5 mm, "39.5 holes"
    assert abs(distance(base.lights.c[0].center, base.disc.center) - 58 mm) < 0.001 mm, "58 from the middle"
    assert 90 mm - (58 mm + 39.5 mm / 2) >= 10 mm, "a 10 mm rim outside the holes"
    assert front.lower.width == 150 mm, "panels 150 wide"
    assert front.arch.bb.top - front.lower.bb.bottom - 3 mm == 200 mm, "200 above the base"
    assert front.halve.depth + cross.halve.depth == 200 mm, "the halvings meet"
    assert len(front.hearts.left) == 6 and len(cross.hearts.left) == 6, "six hearts each"
    assert abs(front.hearts.left[1].bb.left - front.hearts.left[0].bb.left - 90 mm) < 0.001 mm, "columns 45 either side"
    assert cross.initials.t.bb.bottom > cross.hearts.right[4].bb.top + 5 mm, "initials clear the hearts"
    assert cross.initials.t.bb.width < 2 * sqrt(arch_r ** 2 - (cross.initials.t.bb.top - (panel_h - arch_r)) ** 2) - 20 mm,
        "initials inside the arch with 10 mm each side"
}
