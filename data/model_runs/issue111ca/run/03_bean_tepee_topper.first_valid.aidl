# Request (garden): a bean-tepee topper that gathers six bamboo canes (up to 12 mm thick) into
# a wigwam, from 6 mm exterior ply. A 100 mm top disc with the six cane holes evenly on a
# 60 mm circle, and a 160 mm lower disc with them on a 120 mm circle, the discs' facing sides
# 60 mm apart, so each cane runs through both at the tepee's lean; the holes are slots along
# the radius, long enough for a 12 mm cane at that lean with 1 mm play. The discs are held by
# two 40 mm wide fins, cross-halved, each tenoned through both discs by two 10 mm tabs.
# "RUNNER BEANS" engraved round the lower disc, inside its cane holes.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
cane = 12 mm
play = 1 mm
top_d = 100 mm
low_d = 160 mm
top_pcd = 60 mm
low_pcd = 120 mm
gap = 60 mm                      # between the discs' facing sides
fin_w = 40 mm
fin_h = gap + 2 * T              # tabs through both discs, flush outside

rise = gap + T                   # between the discs' mid-planes
lean = atan((low_pcd - top_pcd) / 2 / rise)
hole_len = (cane + play) / cos(lean) + T * tan(lean)

def cane_disc(d, pcd) -> solid {
    disc = Circle(center=(0, 0), diameter=d)
    for i in range(6) {
        hole cane_hole {
            s = Slot(center=polar((0, 0), pcd / 2, i * 60 deg), length=hole_len,
                     width=cane + play, rotation=i * 60 deg)
        }
    }
    along_x = tab_and_slot(part="slot", length=fin_w, thickness=T, tabs=2, tab=10 mm, screw=0,
                           cx=0, cy=0)
    along_y = tab_and_slot(part="slot", length=fin_w, thickness=T, tabs=2, tab=10 mm, screw=0,
                           rotation=90 deg, cx=0, cy=0)
}

def fin(from_top=true) -> solid {
    plate = Rectangle(bottom_left=(-fin_w / 2, 0), width=fin_w, height=fin_h)
    if from_top {
        halving = cross_halving(depth=fin_h / 2, thickness=T, cx=0, cy=fin_h)
    } else {
        halving = cross_halving(depth=fin_h / 2, thickness=T, rotation=180 deg, cx=0, cy=0)
    }
    up = tab_and_slot(part="tab", length=fin_w, thickness=T, tabs=2, tab=10 mm, screw=0,
                      cx=0, cy=fin_h)
    down = tab_and_slot(part="tab", length=fin_w, thickness=T, tabs=2, tab=10 mm, screw=0,
                        rotation=180 deg, cx=0, cy=0)
}

assembly topper {
    top = cane_disc(d=top_d, pcd=top_pcd)
    low = cane_disc(d=low_d, pcd=low_pcd)
    drawing words {
        ring = Circle(center=(0, 0), radius=35, construction=true)
        t = Text("RUNNER BEANS", along=ring, size=8, font="sans:Bold", fill=true)
    }
    CutInto(words, low)
    Concentric(words.ring, low.disc)
    fin_a = fin(from_top=true)
    fin_b = fin(from_top=false)

    # flat on the sheet
    low.disc.center == (0, 0)
    RightOf(top, low, gap=6)
    AlignTop(top, low)
    RightOf(fin_a, low, gap=6)
    Below(fin_a, top, gap=6)
    RightOf(fin_b, fin_a, gap=6)
    AlignTop(fin_b, fin_a)

    # in 3D: lower disc on the ground, fins on it, top disc on the fins
    Place(low, position=(0, 0, 0))
    Place(top, position=(0, 0, T + gap))
    Place(fin_a, rotation=(90 deg, 0, 0), position=(0, T / 2, 0))
    Place(fin_b, rotation=(90 deg, 0, 90 deg), position=(-T / 2, 0, 0))

    assert top.disc.diameter == 100 mm and low.disc.diameter == 160 mm, "discs 100 and 160"
    assert distance(top.cane_hole[0].s.center, top.cane_hole[3].s.center) == 60 mm, "60 mm circle"
    assert distance(low.cane_hole[0].s.center, low.cane_hole[3].s.center) == 120 mm, "120 mm circle"
    assert len(low.cane_hole) == 6, "six canes"
    assert top.cane_hole[0].s.width == 13 mm, "12 mm cane, 1 mm play"
    # the fins stay clear of the canes: a cane's inner edge, at the top disc, is outside them
    assert top_pcd / 2 - hole_len / 2 > fin_w / 2, "fins clear of the canes"
    # the lettering stays clear of the lower disc's cane holes
    assert 35 mm + 8 mm < low_pcd / 2 - hole_len / 2, "words inside the cane holes"
}
