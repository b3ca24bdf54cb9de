# Request (kitchen): a toast rack in 4 mm birch ply. A base 190 x 90 mm with 8 mm round
# corners; five upright dividers 70 mm wide on 35 mm centres (the middle one on the base's
# centre), glued into the base by two 15 mm tabs each (4 mm tall tabs into closed mortises,
# 0.2 mm clearance). The four outer dividers stand 80 mm above the base, the middle one 120 mm;
# all have 20 mm rounded top corners. The middle divider is the handle: a 50 x 18 mm finger
# slot centred 20 mm below its top, and "TOAST" engraved as filled bold letters 10 mm tall,
# centred 50 mm above the base.

import "std/joints.aidl"

thickness 4 mm

mat = 4 mm
param pitch = 35 mm, min = 28 mm, max = 45 mm
param low = 80 mm, min = 50 mm, max = 110 mm
param high = 120 mm, min = 90 mm, max = 160 mm
divider_w = 70 mm

def divider(above=80 mm, handle=false) -> solid {
    # y = 0 is the tabs' tips; the shoulders sit on the base at y = mat
    body = RoundedRectangle(center=(0, (above + mat) / 2), width=divider_w, height=above + mat,
                            corner_radii=[20, 20, 0, 0])
    t = tab_and_slot(part="tab", length=divider_w, thickness=mat, tabs=2, tab=15 mm, screw=0,
                     rotation=180 deg, cx=0 mm, cy=0 mm)
    if handle {
        hole grip {
            s = Slot(center=(0, mat + above - 20 mm), length=50, width=18)
        }
        drawing word {
            w = Text("TOAST", position=(0, mat + 50 mm), size=10, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }
}

assembly toast_rack {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=190, height=90, corner_radius=8)
        for i in range(5) {
            m = tab_and_slot(part="slot", length=divider_w, thickness=mat, tabs=2, tab=15 mm,
                             screw=0, clearance=0.2 mm, rotation=90 deg, cx=(i - 2) * pitch, cy=0 mm)
        }
    }
    d1 = divider(above=low)
    d2 = divider(above=low)
    mid = divider(above=high, handle=true)
    d4 = divider(above=low)
    d5 = divider(above=low)

    RightOf(d1, base, gap=8)
    RightOf(d2, d1, gap=5)
    RightOf(mid, d2, gap=5)
    RightOf(d4, mid, gap=5)
    RightOf(d5, d4, gap=5)
    AlignBottom(d1, base)
    AlignBottom(d2, base)
    AlignBottom(mid, base)
    AlignBottom(d4, base)
    AlignBottom(d5, base)

    # the request's numbers
    assert base.plate.bb.width == 190 mm and base.plate.bb.height == 90 mm, "base 190 x 90"
    assert len(base.m) == 5, "five dividers"
    assert abs(base.m[1].bb.center_x - base.m[0].bb.center_x - 35 mm) < 0.01 mm, "35 mm centres"
    assert abs(base.m[2].bb.center_x - base.plate.bb.center_x) < 0.01 mm, "middle divider on the centre"
    assert d1.body.bb.width == 70 mm, "dividers 70 mm wide"
    assert d1.body.bb.height - 4 mm == 80 mm, "outer dividers 80 mm above the base"
    assert mid.body.bb.height - 4 mm == 120 mm, "middle divider 120 mm above the base"
    assert mid.body.bb.top - mid.grip.s.center.y == 20 mm, "finger slot 20 mm below the top"
    assert mid.grip.s.length == 50 mm and mid.grip.s.width == 18 mm, "finger slot 50 x 18"
    assert abs(mid.word.w.position.y - (mid.body.bb.bottom + 4 mm) - 50 mm) < 0.01 mm, "TOAST 50 mm above the base"
    assert pitch - mat >= 25 mm, "room for a thick slice between dividers"
}
