# Request (parties): a fruit-kebab tree for a birthday buffet, 6 mm ply.
# Two uprights 300 mm tall cross-halved into a "+" (one slotted 150 mm down from the top,
# the other 150 mm up from the bottom). Each upright is stepped: 200 mm wide up to 80 mm,
# 150 mm wide to 160 mm, 100 mm wide to 240 mm, then a 40 mm mast with a round top; a
# 120 x 10 mm gap in the bottom edge leaves two feet.
# Three round tiers rest on the steps: 260 mm (on the step at 80 mm), 200 mm (at 160 mm)
# and 140 mm (at 240 mm) across, each with a cross-shaped hole in the middle (arms 6.3 mm
# wide, 1 mm longer than the upright is wide just above its step) and a ring of 5 mm
# skewer holes 15 mm in from the rim: 24, 18 and 12 holes.
# The big tier says "HAPPY BIRTHDAY MIA" over the top and "8 TODAY" under the bottom,
# 9 mm letters on a 92 mm radius.

units mm
thickness 6 mm

import "std/joints.aidl"

t = 6 mm
slot_w = 6.3 mm
H = 300 mm
steps = [80, 160, 240]             # heights of the steps
widths = [200, 150, 100, 40]       # upright width below the first step, then above each
tier_d = [260, 200, 140]
tier_holes = [24, 18, 12]

def upright_outline() = Polygon([(-100, 0), (100, 0), (100, 80), (75, 80), (75, 160), (50, 160),
                                 (50, 240), (20, 240), (20, 280), (-20, 280), (-20, 240),
                                 (-50, 240), (-50, 160), (-75, 160), (-75, 80), (-100, 80)])

def tier(d=200 mm, n=18, arm=100 mm) -> solid {
    disc = Circle(center=(0, 0), diameter=d)
    hole cross {
        a = Rectangle(center=(0, 0), width=arm, height=slot_w)
        b = Rectangle(center=(0, 0), width=slot_w, height=arm)
    }
    hole skewers {
        for i in range(n) {
            c = Circle(center=((d / 2 - 15 mm) * cos(i * 360 deg / n), (d / 2 - 15 mm) * sin(i * 360 deg / n)),
                       diameter=5)
        }
    }
}

assembly kebab_tree {
    solid upright_a {
        body = upright_outline()
        cap = Circle(center=(0, 280), radius=20)
        hole feet { g = Rectangle(corner=(-60, -1), opposite=(60, 10)) }
        halving = cross_halving(depth=H / 2, thickness=t, clearance=0.3 mm, cx=0, cy=H)
    }
    solid upright_b {
        body = upright_outline()
        cap = Circle(center=(0, 280), radius=20)
        hole feet { g = Rectangle(corner=(-60, -1), opposite=(60, 10)) }
        halving = cross_halving(depth=H / 2, thickness=t, clearance=0.3 mm, rotation=180 deg, cx=0, cy=0)
    }

    tier1 = tier(d=tier_d[0], n=tier_holes[0], arm=widths[1] + 1 mm)
    tier2 = tier(d=tier_d[1], n=tier_holes[1], arm=widths[2] + 1 mm)
    tier3 = tier(d=tier_d[2], n=tier_holes[2], arm=widths[3] + 1 mm)

    drawing greeting {
        ring = Circle(center=(0, 0), radius=92, construction=true)
        top = Text("HAPPY BIRTHDAY MIA", along=ring, size=9, valign="middle")
        bottom = Text("8 TODAY", along=ring, size=9, valign="middle", flip=true)
    }
    Concentric(greeting.ring, tier1.disc)
    CutInto(greeting, tier1)

    # 3D: upright_a in the plane y = 0, upright_b in the plane x = 0, tiers on the steps
    Place(upright_a, position=(0, t / 2, 0), face="front", up="up")
    Place(upright_b, position=(t / 2, 0, 0), face="left", up="up")
    Place(tier1, position=(0, 0, steps[0]))
    Place(tier2, position=(0, 0, steps[1]))
    Place(tier3, position=(0, 0, steps[2]))

    # on the sheet
    RightOf(upright_b, upright_a, gap=10)
    AlignBottom(upright_b, upright_a)
    RightOf(tier1, upright_b, gap=10)
    AlignBottom(tier1, upright_a)
    Above(tier2, upright_a, gap=10)
    AlignLeft(tier2, upright_a)
    RightOf(tier3, tier2, gap=10)
    AlignBottom(tier3, tier2)

    assert upright_a.body.bb.height + 20 mm == 300 mm, "300 mm tall with the round top"
    assert upright_a.body.bb.width == 200 mm, "200 wide at the foot"
    assert tier1.disc.diameter == 260 mm and tier2.disc.diameter == 200 mm and tier3.disc.diameter == 140 mm, "tiers"
    assert len(tier1.skewers.c) == 24 and len(tier2.skewers.c) == 18 and len(tier3.skewers.c) == 12, "hole counts"
    assert abs(distance(tier1.skewers.c[0].center, tier1.disc.center) - (130 mm - 15 mm)) < 0.01 mm, "15 in from the rim"
    assert tier1.cross.a.width < widths[0] and tier1.cross.a.width > widths[1], "tier 1 rests on the 80 mm step"
    assert tier2.cross.a.width < widths[1] and tier2.cross.a.width > widths[2], "tier 2 rests on the 160 mm step"
    assert tier3.cross.a.width < widths[2] and tier3.cross.a.width > widths[3], "tier 3 rests on the 240 mm step"
    assert upright_a.halving.depth + upright_b.halving.depth == 300 mm, "the halvings meet"
    assert upright_a.feet.g.width == 120 mm, "120 mm gap between the feet"
}
