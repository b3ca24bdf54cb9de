# Standing Christmas table tree (gifts / home decoration). Full sizes: two identical tree
# panels in 3 mm ply, slotted together crosswise (cross halving) so the tree stands on its
# own. Each panel: a trunk 20 mm wide and 20 mm high at the bottom; on it three triangular
# tiers, centred: the lowest 120 mm wide at its base and 60 mm high, its base on the trunk's
# top; the middle one 95 mm wide and 55 mm high, its base 35 mm above the lowest's base; the
# top one 70 mm wide and 52 mm high, its base 33 mm above the middle's base (apex 140 mm
# above the ground). Panel A has a slot from the apex down 70 mm, panel B a slot from the
# trunk's bottom up 70 mm, both on the centre line, 3 mm + 0.1 mm clearance wide. The two
# panels lie side by side on the sheet, 10 mm apart.

import "std/joints.aidl"

units mm
thickness 3 mm

def tree_panel(x0=0 mm, from_top=true) -> solid {
    trunk = Rectangle(center=(x0, 10), width=20, height=20)
    low = Triangle(center=(x0, 50), base=120, height=60)
    mid = Triangle(center=(x0, 82.5), base=95, height=55)
    top = Triangle(center=(x0, 114), base=70, height=52)
    low.bb.bottom == trunk.bb.top
    mid.bb.bottom == low.bb.bottom + 35
    top.bb.bottom == mid.bb.bottom + 33
    AlignCenterX(low, trunk)
    AlignCenterX(mid, trunk)
    AlignCenterX(top, trunk)
    if from_top {
        s = cross_halving(depth=70 mm, thickness=3 mm, clearance=0.1 mm, cx=x0, cy=140)
    } else {
        s = cross_halving(depth=70 mm, thickness=3 mm, clearance=0.1 mm, rotation=180 deg,
                          cx=x0, cy=0)
    }
}

assembly tree {
    a = tree_panel(x0=0 mm, from_top=true)
    b = tree_panel(x0=130 mm, from_top=false)

    assert a.bb.width == 120 mm and a.bb.height == 140 mm, "panel 120 x 140"
    assert b.bb.width == 120 mm and b.bb.height == 140 mm, "panel 120 x 140"
    assert a.trunk.width == 20 mm and a.trunk.height == 20 mm, "trunk 20 x 20"
    assert a.low.bb.width == 120 mm and a.low.bb.height == 60 mm, "lowest tier"
    assert a.mid.bb.width == 95 mm and a.mid.bb.height == 55 mm, "middle tier"
    assert a.top.bb.width == 70 mm and a.top.bb.height == 52 mm, "top tier"
    assert a.mid.bb.bottom - a.low.bb.bottom == 35 mm, "middle tier 35 mm up"
    assert a.top.bb.bottom - a.mid.bb.bottom == 33 mm, "top tier 33 mm up"
    assert a.s.cut.bb.height == 70 mm and b.s.cut.bb.height == 70 mm, "slots 70 mm deep"
    assert a.s.cut.bb.width == 3.1 mm, "slot 3.1 mm wide"
    assert a.s.cut.bb.top == a.bb.top, "A's slot from the apex"
    assert b.s.cut.bb.bottom == b.bb.bottom, "B's slot from the trunk's bottom"
    assert abs(a.s.cut.bb.center_x - a.trunk.center.x) < 0.01 mm, "A's slot on the centre line"
    assert abs(b.s.cut.bb.center_x - b.trunk.center.x) < 0.01 mm, "B's slot on the centre line"
    assert b.bb.left - a.bb.right == 10 mm, "10 mm apart on the sheet"
}
