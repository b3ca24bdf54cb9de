# Request (science): a flat-pack water molecule model for a classroom, 3 mm poplar ply, five
# parts that slot together at right angles (cross halvings, 3 mm + 0.1 mm wide): an oxygen atom,
# a 40 mm disc with "O" engraved as a filled bold letter 14 mm tall in its centre and two slots
# 6 mm deep cut in from its rim 104.5 degrees apart (the H-O-H angle), symmetric about the
# downward vertical; two hydrogen atoms, 28 mm discs each with one 6 mm slot at the top and "H"
# engraved filled bold 8 mm tall, centred 1 mm below the disc's centre; and two bonds, 40 x 10 mm
# strips with a 6 mm slot along their axis in from each end. Parts laid out in a row, 5 mm apart.

import "std/joints.aidl"

thickness 3 mm

param ply = 3 mm, min = 2.5 mm, max = 4 mm
param fit = 0.1 mm, min = 0 mm, max = 0.3 mm
param slot_d = 6 mm, min = 4 mm, max = 8 mm

def atom(d, label, size, slots, dy=0 mm) -> solid {
    disc = Circle(center=(0, 0), diameter=d)
    for k in range(len(slots)) {
        s = cross_halving(depth=slot_d, thickness=ply, clearance=fit, rotation=slots[k] - 90 deg,
                          cx=d / 2 * cos(slots[k]), cy=d / 2 * sin(slots[k]))
    }
    drawing mark {
        t = Text(label, position=(0, dy), size=size, font="sans:Bold", valign="middle", fill=true)
    }
}

def bond() -> solid {
    strip = Rectangle(center=(0, 0), width=40, height=10)
    e1 = cross_halving(depth=slot_d, thickness=ply, clearance=fit, rotation=90 deg, cx=-20 mm, cy=0 mm)
    e2 = cross_halving(depth=slot_d, thickness=ply, clearance=fit, rotation=-90 deg, cx=20 mm, cy=0 mm)
}

assembly water {
    oxygen = atom(40 mm, "O", 14 mm, [270 deg - 52.25 deg, 270 deg + 52.25 deg])
    h1 = atom(28 mm, "H", 8 mm, [90 deg], dy=-1 mm)
    h2 = atom(28 mm, "H", 8 mm, [90 deg], dy=-1 mm)
    b1 = bond()
    b2 = bond()
    RightOf(h1, oxygen, gap=5)
    RightOf(h2, h1, gap=5)
    RightOf(b1, h2, gap=5)
    RightOf(b2, b1, gap=5)
    AlignCenterY(h1, oxygen)
    AlignCenterY(h2, oxygen)
    AlignCenterY(b1, oxygen)
    AlignCenterY(b2, oxygen)

    assert oxygen.disc.diameter == 40 mm and h1.disc.diameter == 28 mm, "O 40, H 28"
    assert len(oxygen.s) == 2 and len(h1.s) == 1 and len(h2.s) == 1, "O two slots, H one each"
    assert abs(oxygen.s[1].rotation - oxygen.s[0].rotation - 104.5 deg) < 0.01 deg, "H-O-H 104.5 deg"
    assert oxygen.s[0].depth + b1.e1.depth == 12 mm, "disc slot + bond slot = 6 + 6"
    assert b1.strip.bb.width == 40 mm and b1.strip.bb.height == 10 mm, "bond 40 x 10"
    assert oxygen.mark.t.size == 14 mm and h1.mark.t.size == 8 mm, "letters 14 and 8 tall"
    assert abs(h1.disc.center.y - h1.mark.t.position.y - 1 mm) < 0.01 mm, "H 1 mm below centre"
}
