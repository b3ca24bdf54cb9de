# Request: an agarose gel casting tray for a mini electrophoresis tank, from 3 mm clear
# acrylic. A base 100 x 70. Two side walls 100 long standing 12 mm above the base, each on
# two 20 mm tenons through it, 60 mm apart inside. Two removable end dams 70 wide and 12 tall
# that drop into 3.2 mm slots 10 mm deep in the wall tops, 90 mm apart (centres), the dams
# notched 2 mm at the bottom over the walls so they reach the base. A comb 76 long and 10
# tall with eight teeth 5 wide at 7 mm pitch, resting across the walls 10 mm inside the left
# dam in 2 mm notches (3.2 wide) cut in the wall tops and in the comb's bottom edge, its teeth
# ending 2 mm above the base. "-" and "+" engraved at the two ends of the gel area, "COMB 8"
# engraved on the comb.

import "std/joints.aidl"

thickness 3 mm

T = 3 mm
CLR = 0.2 mm
LEN = 100 mm
WALL_H = 12 mm
GEL_W = 60 mm
WALL_Y = GEL_W / 2 + T / 2
DAM_X = 45 mm
COMB_X = -35 mm
TOOTH = 6 mm

def wall() -> solid {
    body = Rectangle(bottom_left=(-LEN / 2, 0), width=LEN, height=T + WALL_H)
    tabs = tab_and_slot(part="tab", length=LEN, thickness=T, tabs=2, tab=20 mm, screw=0,
                        rotation=180 deg, cx=0, cy=0)
    for x in [-DAM_X, DAM_X] {
        dam_slot = cross_halving(depth=10 mm, thickness=T, clearance=CLR, cx=x, cy=T + WALL_H)
    }
    comb_slot = cross_halving(depth=2 mm, thickness=T, clearance=CLR, cx=COMB_X, cy=T + WALL_H)
}

def dam() -> solid {
    body = Rectangle(bottom_left=(-35, 0), width=70, height=WALL_H)
    for s in [-1, 1] {
        notch = cross_halving(depth=2 mm, thickness=T, clearance=CLR, rotation=180 deg,
                              cx=s * WALL_Y, cy=0)
    }
}

assembly tray {
    solid base {
        body = Rectangle(center=(0, 0), width=LEN, height=70)
        for s in [-1, 1] {
            m = tab_and_slot(part="slot", length=LEN, thickness=T, tabs=2, tab=20 mm, screw=0,
                             cx=0, cy=s * WALL_Y)
        }
        drawing ends {
            minus = Text("-", position=(-DAM_X + 6, -22), size=6, valign="middle")
            plus = Text("+", position=(DAM_X - 6, -22), size=6, valign="middle")
        }
    }
    wall_a = wall()
    wall_b = wall()
    dam_a = dam()
    dam_b = dam()

    solid comb {
        bar = Rectangle(bottom_left=(-38, 0), width=76, height=10)
        for i in range(8) {
            tooth = Rectangle(bottom_left=((i - 3.5) * 7 - 2.5, -TOOTH), width=5, height=TOOTH + 0.5)
        }
        for s in [-1, 1] {
            notch = cross_halving(depth=2 mm, thickness=T, clearance=CLR, rotation=180 deg,
                                  cx=s * WALL_Y, cy=0)
        }
        drawing label {
            t = Text("COMB 8", position=(0, 5), size=4, valign="middle")
        }
    }

    # flat on the sheet
    RightOf(wall_a, base, gap=6)
    AlignTop(wall_a, base)
    Below(wall_b, wall_a, gap=6)
    AlignLeft(wall_b, wall_a)
    Below(dam_a, wall_b, gap=6)
    AlignLeft(dam_a, wall_a)
    RightOf(dam_b, dam_a, gap=6)
    AlignTop(dam_b, dam_a)
    Below(comb, base, gap=6)
    AlignLeft(comb, base)

    # in 3D: the base on z = 0, walls along x, dams and comb across
    Place(base, position=(0, 0, 0), face="up")
    Place(wall_a, position=(0, WALL_Y + T / 2, 0), face="front", up="up")
    Place(wall_b, position=(0, -WALL_Y + T / 2, 0), face="front", up="up")
    Place(dam_a, position=(-DAM_X - T / 2, 0, T), face="right", up="up")
    Place(dam_b, position=(DAM_X - T / 2, 0, T), face="right", up="up")
    Place(comb, position=(COMB_X - T / 2, 0, T + WALL_H - 2 mm - 2 mm), face="right", up="up")

    assert base.body.bb.width == 100 mm and base.body.bb.height == 70 mm, "base 100 x 70"
    assert base.m[1].slot[0].bb.bottom - base.m[0].slot[0].bb.top == 60 mm, "60 inside"
    assert wall_a.body.bb.height - T == 12 mm, "walls 12 above the base"
    assert wall_a.dam_slot[1].cut.bb.center_x - wall_a.dam_slot[0].cut.bb.center_x == 90 mm,
        "dams 90 apart"
    assert wall_a.dam_slot[0].cut.bb.height + dam_a.notch[0].cut.bb.height == 12 mm,
        "dams reach the base"
    assert len(comb.tooth) == 8, "eight teeth"
    assert comb.tooth[1].bb.left - comb.tooth[0].bb.left == 7 mm, "7 mm pitch"
    assert 12 mm - wall_a.comb_slot.cut.bb.height - comb.notch[0].cut.bb.height - TOOTH == 2 mm,
        "teeth end 2 above the base"
    assert wall_a.comb_slot.cut.bb.center_x - wall_a.dam_slot[0].cut.bb.center_x == 10 mm,
        "comb 10 inside the left dam"
}
