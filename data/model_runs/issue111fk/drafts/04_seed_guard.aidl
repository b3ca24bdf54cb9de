# Request: a seed guard for my budgies' cage, in 3 mm clear acrylic: a 110 mm tall skirt
# of four walls standing on the table round the cage's 460 x 280 base, 3 mm clear all
# round (inside 466 x 286), the corners finger-jointed (15 mm fingers) and glued. The back
# and the two ends get a scalloped top edge: half-circles 24 mm across, 40 mm apart, as
# many as fit with 30 mm of plain wall at each end. The front has a U-opening 140 wide and
# 50 deep in the middle of its top edge (bottom corners R10) so I can reach the food dishes.
# The birds' names, "KIWI" and "PIP", engraved filled (sans bold, 14 mm) on the two ends.

units mm
thickness 3 mm

import "std/joints.aidl"

T = 3 mm
H = 110 mm
IN_L = 466 mm
IN_W = 286 mm
OUT_L = IN_L + 2 * T
OUT_W = IN_W + 2 * T
SC_D = 24 mm
SC_PITCH = 40 mm

def wall(w, ends="fingers", scallops=true, door=false, name="") -> solid {
    p = finger_panel(width=w, height=H, thickness=T, finger=15 mm, bottom="flat", top="flat",
                     left=ends, right=ends)
    if scallops {
        n = floor((w - 2 * 30 mm - SC_D) / SC_PITCH) + 1
        for i in range(n) {
            hole scallop { c = Circle(center=((i - (n - 1) / 2) * SC_PITCH, H / 2), diameter=SC_D) }
        }
    }
    if door {
        hole opening {
            u = RoundedRectangle(center=(0, H / 2 - 20), width=140, height=60,
                                 corner_radii=[0, 0, 10, 10])
        }
    }
    if name != "" {
        drawing label {
            t = Text(name, position=(0, -15), size=14, font="sans:Bold", valign="middle", fill=true)
        }
    }
}

assembly seed_guard {
    front = wall(OUT_L, scallops=false, door=true)
    back = wall(OUT_L)
    left_end = wall(OUT_W, ends="slots", name="KIWI")
    right_end = wall(OUT_W, ends="slots", name="PIP")

    Below(back, front, gap=10)
    AlignLeft(back, front)
    Below(left_end, back, gap=10)
    AlignLeft(left_end, back)
    RightOf(right_end, left_end, gap=10)
    AlignTop(right_end, left_end)

    Place(front, position=(0, -(OUT_W / 2 - T), H / 2), face="front", up="up")
    Place(back, position=(0, OUT_W / 2 - T, H / 2), face="back", up="up")
    Place(left_end, position=(-(OUT_L / 2 - T), 0, H / 2), face="left", up="up")
    Place(right_end, position=(OUT_L / 2 - T, 0, H / 2), face="right", up="up")

    assert front.p.outline.width - 2 * 3 mm == 466 mm, "inside 466 long"
    assert left_end.p.outline.width - 2 * 3 mm == 286 mm, "inside 286 wide"
    assert IN_L - 460 mm == 6 mm and IN_W - 280 mm == 6 mm, "3 mm clear all round the cage"
    assert front.p.outline.height == 110 mm, "110 tall"
    assert front.opening.u.width == 140 mm, "opening 140 wide"
    assert front.p.outline.bb.top - front.opening.u.bb.bottom == 50 mm, "opening 50 deep"
    assert back.scallop[0].c.bb.left - back.p.outline.bb.left >= 30 mm, "30 mm plain at the ends"
    assert back.scallop[1].c.center.x - back.scallop[0].c.center.x == 40 mm, "scallops 40 apart"
}
