# Request: a two-tier hanging planter for the garden porch, 9 mm exterior
# plywood. The top tier is a disc 160 mm across with a 70 mm hole that a small
# herb pot drops into (its rim holds it); the bottom tier is a disc 200 mm
# across with a 100 mm hole for a 12 cm terracotta pot. Each tier has three 8 mm
# holes for the hanging ropes, 120 degrees apart, the top tier's on a 140 mm
# circle and the bottom tier's on a 170 mm circle (the ropes splay out). A ring
# of 12 engraved leaves runs round each pot hole, between it and the ropes.

import "std/shapes.aidl"

units mm
thickness 9 mm

param rope_d = 8 mm, min = 5 mm, max = 12 mm
param leaves = 12, min = 6, max = 20

def tier(d=200 mm, pot=100 mm, pcd=170 mm) -> solid {
    disc = Circle(center=(0, 0), diameter=d)
    hole pot_hole {
        c = Circle(center=(0, 0), diameter=pot)
    }
    ropes = bolt_circle(count=3, pcd=pcd, hole_d=rope_d, start=90 deg)
    drawing leaf_ring {
        leaf = Ellipse(center=((pot / 2 + pcd / 2 - rope_d / 2) / 2, 0), rx=7, ry=3)
        ring = CircularPattern(leaf, leaves, (0, 0), start_angle=15 deg)
    }
}

assembly planter {
    top = tier(d=160 mm, pot=70 mm, pcd=140 mm)
    bottom = tier(d=200 mm, pot=100 mm, pcd=170 mm)
    RightOf(bottom, top, gap=10)
    AlignCenterY(bottom, top)

    assert top.disc.diameter == 160 mm and top.pot_hole.c.diameter == 70 mm, "top tier 160 / 70"
    assert bottom.disc.diameter == 200 mm and bottom.pot_hole.c.diameter == 100 mm, "bottom tier 200 / 100"
    assert len(top.ropes.bolt) == 3 and len(bottom.ropes.bolt) == 3, "three rope holes a tier"
    assert top.ropes.bolt[0].diameter == 8 mm, "rope holes 8 mm"
    assert top.ropes.pitch.diameter == 140 mm and bottom.ropes.pitch.diameter == 170 mm, "rope circles"
    assert len(top.leaf_ring.ring) == 12, "12 leaves a tier"
}
