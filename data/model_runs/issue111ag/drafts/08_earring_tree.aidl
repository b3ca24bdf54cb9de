# Request (gifts): an earring tree as a birthday present, 3 mm ply, no glue.
# - two identical tree silhouettes 170 mm tall (tenon included): a trunk 20 mm wide up
#   to 70 mm and a round crown 110 mm across centred 115 mm up; they cross-halve at the
#   centre line into a 3D tree (one slotted 85 mm up from the bottom, the other 85 mm
#   down from the top);
# - earring holes 1.6 mm across: 24 on a 90 mm circle and 16 on a 60 mm circle about the
#   crown's centre, turned half a step so none sits on the centre line;
# - a 14 mm tenon under each trunk into a plus-shaped mortise in a round base 100 mm
#   across; "FOR ANNA" engraved 6 mm tall over the top of the base on a 38 mm radius;
# - joints 0.15 mm loose.

import "std/joints.aidl"

units mm
thickness 3 mm

T = 3 mm
fit = 0.15 mm
tree_h = 170 mm
crown_y = 115 mm
crown_d = 110 mm
trunk_w = 20 mm
trunk_h = 70 mm
tenon = 14 mm
ring1_r = 45 mm
ring2_r = 30 mm
ring1_n = 24
ring2_n = 16
earring_d = 1.6 mm

def tree_panel(slot_from_top=false) -> solid {
    trunk = Rectangle(center=(0, trunk_h / 2), width=trunk_w, height=trunk_h)
    crown = Circle(center=(0, crown_y), diameter=crown_d)
    Fixed(trunk)
    Fixed(crown)
    hole outer {
        c = Circle(center=(ring1_r * cos(180 deg / ring1_n), crown_y + ring1_r * sin(180 deg / ring1_n)),
                   diameter=earring_d)
    }
    outer_ring = CircularPattern(outer, ring1_n, crown.center)
    hole inner {
        c = Circle(center=(ring2_r * cos(180 deg / ring2_n), crown_y + ring2_r * sin(180 deg / ring2_n)),
                   diameter=earring_d)
    }
    inner_ring = CircularPattern(inner, ring2_n, crown.center)
    foot = tab_and_slot(part="tab", length=trunk_w, thickness=T, tabs=1, tab=tenon, screw=0,
                        rotation=180 deg, cx=0, cy=0)
    if slot_from_top {
        halving = cross_halving(depth=tree_h / 2, thickness=T, clearance=fit, cx=0, cy=tree_h)
    } else {
        halving = cross_halving(depth=tree_h / 2, thickness=T, clearance=fit, rotation=180 deg,
                                cx=0, cy=0)
    }
}

assembly earring_tree {
    tree_a = tree_panel(slot_from_top=false)
    tree_b = tree_panel(slot_from_top=true)

    solid base {
        disc = Circle(center=(0, 0), diameter=100)
        Fixed(disc)
        mortise_a = tab_and_slot(part="slot", length=trunk_w, thickness=T, tabs=1, tab=tenon,
                                 screw=0, clearance=fit, rotation=0 deg, cx=0, cy=0)
        mortise_b = tab_and_slot(part="slot", length=trunk_w, thickness=T, tabs=1, tab=tenon,
                                 screw=0, clearance=fit, rotation=90 deg, cx=0, cy=0)
        # FIX after the first valid program: the two mortises are meant as one plus-shaped
        # opening (W0508 was a false alarm for this design); said so as its hint offers
        AllowOverlap(mortise_a, mortise_b)
        drawing gift {
            ring = Circle(center=(0, 0), radius=38, construction=true)
            t = Text("FOR ANNA", along=ring, size=6)
        }
    }

    Fixed(tree_a)
    RightOf(tree_b, tree_a, gap=10)
    AlignBottom(tree_b, tree_a)
    RightOf(base, tree_b, gap=10)
    AlignBottom(base, tree_b)

    assert tree_a.bb.height == 170 mm, "tree 170 tall"
    assert tree_a.crown.diameter == 110 mm and tree_a.crown.center.y - tree_a.bb.bottom == 115 mm, "crown 110 at 115"
    assert tree_a.trunk.bb.width == 20 mm, "trunk 20 wide"
    assert len(tree_a.outer_ring) == 24 and len(tree_a.inner_ring) == 16, "24 + 16 earring holes"
    assert abs(tree_a.outer_ring[5].c.center.x - tree_a.crown.center.x) > 3 mm, "no hole on the centre line"
    assert tree_a.halving.depth + tree_b.halving.depth == 170 mm, "halvings add up to the height"
    assert base.disc.diameter == 100 mm, "base 100 across"
    assert base.gift.bb.top < base.disc.bb.top, "gift text on the base"
}
