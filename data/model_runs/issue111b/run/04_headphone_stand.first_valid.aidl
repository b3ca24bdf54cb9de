# Headphone stand, 4 mm plywood: two identical panels that cross-halve into an X-shaped stand.
# Each panel is 250 mm tall: a foot bar 140 x 15 mm at the bottom, a 40 mm wide column, and a
# saddle 120 x 30 mm (R10 corners) at the top. Panel A is slotted from the top edge down
# 125 mm, panel B from the bottom edge up 125 mm, slots 4 mm + 0.2 mm clearance wide,
# centered on the column. Parts laid out side by side, 10 mm apart.

import "std/joints.aidl"

units mm
thickness 4 mm

param height = 250 mm, min = 180 mm, max = 320 mm
param t = 4 mm, min = 3 mm, max = 6 mm

def stand_panel(h=250 mm) -> solid {
    foot = Rectangle(center=(0, 7.5), width=140, height=15)
    column = Rectangle(center=(0, h / 2), width=40, height=h)
    saddle = RoundedRectangle(center=(0, h - 15 mm), width=120, height=30, corner_radius=10)
}

assembly stand {
    solid a {
        p = stand_panel(h=height)
        slot = cross_halving(depth=height / 2, thickness=t, clearance=0.2 mm, cx=0 mm, cy=height)
    }
    solid b {
        p = stand_panel(h=height)
        slot = cross_halving(depth=height / 2, thickness=t, clearance=0.2 mm, rotation=180 deg,
                             cx=0 mm, cy=0 mm)
    }
    RightOf(b, a, gap=10 mm)
    AlignBottom(b, a)

    assert abs(a.p.bb.height - 250 mm) < 0.001 mm, "panel 250 mm tall"
    assert abs(a.p.foot.width - 140 mm) < 0.001 mm, "foot 140 mm"
    assert abs(a.p.saddle.width - 120 mm) < 0.001 mm, "saddle 120 mm"
    assert abs(a.slot.cut.bb.height - 125 mm) < 0.001 mm, "A slotted 125 mm from the top"
    assert abs(b.slot.cut.bb.height - 125 mm) < 0.001 mm, "B slotted 125 mm from the bottom"
    assert abs(a.slot.cut.bb.width - 4.2 mm) < 0.001 mm, "slot 4.2 mm wide"
    assert abs(a.slot.cut.bb.top - a.p.bb.top) < 0.001 mm, "A's slot opens at the top"
    assert abs(b.slot.cut.bb.bottom - b.p.bb.bottom) < 0.001 mm, "B's slot opens at the bottom"
}
