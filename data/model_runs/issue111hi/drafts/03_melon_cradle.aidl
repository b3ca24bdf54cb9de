# Request (garden): a melon cradle that holds a ripening melon or squash off the
# damp soil, in 6 mm exterior ply. A round top 200 mm across, drained by 10 mm
# holes on a staggered 18 mm pitch (rows 15.6 mm apart) reaching no further than
# 78 mm from the centre and kept 15 mm clear of the two leg lines. Two crossed
# legs, each 180 mm long and 40 mm tall below the top, with a shallow arch
# 100 mm wide and 10 mm high under the middle so each stands on two feet; they
# cross by a halving (one slotted 15 mm down from the top, the other 15 mm up
# from the arch, 0.1 mm clearance) and each has two 20 mm tabs up into the top
# (0.1 mm clearance in its mortises), so the top sits 46 mm above the soil.

import "std/joints.aidl"

t = 6 mm
thickness t

def hx(i, j) = i * 18 + 9 * (abs(j) % 2)
def hy(j) = j * 15.6

def leg(from_top=true) -> solid {
    body = Rectangle(center=(0, 23), width=180, height=46)
    tabs = tab_and_slot(part="tab", length=180 mm, thickness=t, tabs=2, tab=20 mm,
                        screw=0, cx=0 mm, cy=46 mm)
    hole arch {
        a = Ellipse(center=(0, 0), rx=50, ry=10)
    }
    if from_top {
        h = cross_halving(depth=15 mm, thickness=t, clearance=0.1 mm, cx=0 mm, cy=40 mm)
    } else {
        h = cross_halving(depth=15 mm, thickness=t, clearance=0.1 mm, rotation=180 deg,
                          cx=0 mm, cy=10 mm)
    }
    assert body.bb.height - t == 40 mm, "40 mm tall below the top"
    assert arch.bb.width == 100 mm, "arch 100 mm wide"
}

assembly cradle {
    solid top {
        disc = Circle(center=(0, 0), diameter=200)
        mortise_a = tab_and_slot(part="slot", length=180 mm, thickness=t, tabs=2, tab=20 mm,
                                 screw=0, clearance=0.1 mm, cx=0 mm, cy=0 mm)
        mortise_b = tab_and_slot(part="slot", length=180 mm, thickness=t, tabs=2, tab=20 mm,
                                 screw=0, clearance=0.1 mm, rotation=90 deg, cx=0 mm, cy=0 mm)
        hole drain {
            for j in range(-5, 6) {
                for i in range(-5, 6) {
                    if (sqrt(hx(i, j) ** 2 + hy(j) ** 2) <= 78 and abs(hx(i, j)) >= 15
                        and abs(hy(j)) >= 15) {
                        c = Circle(center=(hx(i, j), hy(j)), diameter=10)
                    }
                }
            }
        }
        assert disc.diameter == 200 mm, "200 mm across"
        assert distance(drain, mortise_a) >= 5 mm, "drain holes clear of leg A's mortises"
        assert distance(drain, mortise_b) >= 5 mm, "drain holes clear of leg B's mortises"
        assert distance(drain.bb.center, disc.center) <= 1 mm, "drain pattern centred"
    }

    leg_a = leg(from_top=true)
    leg_b = leg(from_top=false)
    Below(leg_a, top, gap=10)
    AlignCenterX(leg_a, top)
    Below(leg_b, leg_a, gap=10)
    AlignCenterX(leg_b, top)

    assert leg_a.h.cut.bb.height + leg_b.h.cut.bb.height == 30 mm, "halvings share the 30 mm overlap"
}
