# Request: A vertical dock for my desk that holds my closed laptop (18 mm thick) and my tablet
# (9 mm thick) standing on edge, side by side. 6 mm plywood. A base plate 100 mm wide and
# 110 mm deep with 8 mm rounded corners; three upright fins, each 90 mm long (front to back),
# 76 mm tall at the back sloping down to 41 mm at the front, top corners rounded 6 mm. The gap
# between the first two fins is 19 mm (laptop), between the second and third 10 mm (tablet);
# the fins stand centred on the base both ways. Each fin has two 15 mm tabs glued into
# mortises in the base (0.1 mm clearance), no screws. Show it assembled, and lay it out flat
# for cutting.

units mm
thickness 6 mm

import "std/joints.aidl"

param ply = 6 mm, min = 3 mm, max = 9 mm
param laptop_gap = 19 mm, min = 10 mm, max = 30 mm
param tablet_gap = 10 mm, min = 6 mm, max = 20 mm
param fin_len = 90 mm, min = 60 mm, max = 100 mm

BASE_W = 100 mm
BASE_D = 110 mm
BACK_H = 76 mm
FRONT_H = 41 mm
TAB = 15 mm
# fin centres across the base: the three fins and two gaps centred on x = 0
SPAN = 3 * ply + laptop_gap + tablet_gap
FIN_X = [-SPAN / 2 + ply / 2, -SPAN / 2 + 1.5 * ply + laptop_gap,
         -SPAN / 2 + 2.5 * ply + laptop_gap + tablet_gap]

def fin(length=90 mm, back=76 mm, front=41 mm, ply=6 mm, tab=15 mm) -> solid {
    # drawn on its side: x from the front (0) to the back (length), y up; y = 0 is the tabs'
    # tips, y = ply the base's top face
    side = Polygon([(0, 0), (length, 0), (length, back), (0, front)])
    joint = tab_and_slot(part="tab", length=length, thickness=ply, tabs=2, tab=tab, screw=0,
                         rotation=180 deg, cx=length / 2, cy=0)
    Fillet([side.points[2], side.points[3]], 6 mm)
}

assembly dock {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=BASE_W, height=BASE_D, corner_radius=8)
        for i in range(3) {
            mortise = tab_and_slot(part="slot", length=fin_len, thickness=ply, tabs=2, tab=TAB,
                                   screw=0, clearance=0.1 mm, rotation=90 deg,
                                   cx=FIN_X[i], cy=0)
        }
    }
    for i in range(3) {
        f = fin(length=fin_len, back=BACK_H + ply, front=FRONT_H + ply, ply=ply, tab=TAB)
    }
    # flat on the sheet: the fins in a row above the base
    Above(f[0], base, gap=8)
    AlignLeft(f[0], base)
    for i in range(1, 3) {
        Above(f[i], f[i - 1], gap=8)
        AlignLeft(f[i], f[0])
    }
    # assembled: the base on the desk, each fin stood up along the depth at its mortises
    Place(base, position=(0, 0, 0))
    for i in range(3) {
        Place(f[i], rotation=(90 deg, 0, 90 deg), position=(FIN_X[i] - ply / 2, -fin_len / 2, 0))
    }

    assert len(f) == 3, "three fins"
    assert abs(base.plate.width - 100 mm) < 0.001 mm and abs(base.plate.height - 110 mm) < 0.001 mm,
        "base 100 x 110"
    assert abs(f[0].side.bb.width - 90 mm) < 0.001 mm, "fins 90 mm long"
    assert abs(f[0].side.bb.height - (76 mm + ply)) < 0.001 mm, "76 mm tall at the back above the base"
    assert abs((base.mortise[1].bb.center_x - base.mortise[0].bb.center_x) - (19 mm + ply)) < 0.001 mm,
        "19 mm laptop gap"
    assert abs((base.mortise[2].bb.center_x - base.mortise[1].bb.center_x) - (10 mm + ply)) < 0.001 mm,
        "10 mm tablet gap"
    assert abs((base.mortise[0].bb.center_x + base.mortise[2].bb.center_x) / 2 - base.plate.center.x) < 0.001 mm,
        "fins centred across the base"
}
