# Request: a party "hedgehog" for cheese-and-pineapple sticks, 3 mm birch ply, glued.
# Seen from above it is a hedgehog: an oval body 160 x 124 mm (centred 10 mm behind the middle)
# drawn out into a snout ending in a 12 mm round nose, 201 mm nose to tail. The top plate is
# full of 3.5 mm holes for the cocktail sticks (a honeycomb, 12 mm apart in a row, rows
# 10.4 mm apart, at least 8 mm in from the body's oval and none in front of x = 40 mm, the
# head), with engraved eyes (7 mm dots) and a filled nose. It stands 30 mm above a base
# plate the same shape grown 8 mm all round, on two crossed ribs 3 mm thick and 30 mm tall
# between the plates: a long rib 150 mm along the middle (x -80 to 70) and a short rib 90 mm
# across at x = -20, halved into each other, each with tabs 12 mm wide through mortises in
# both plates (3 on the long rib, 2 on the short). The sticks stand on the base, so no stick
# hole may sit over a rib (holes at least 5 mm from the ribs' centre lines).

import "std/joints.aidl"

t = 3 mm
thickness t
H = 30 mm            # between the plates
RIB_X = -20          # the short rib's line
DX = 12
DY = 10.4
COLS = 11
ROWS = 10
X0 = -82
Y0 = -46.8

def hx(k) = X0 + (k % COLS) * DX + (DX / 2 if (k // COLS) % 2 == 1 else 0)
def hy(k) = Y0 + (k // COLS) * DY
def in_body(k) = ((hx(k) + 10) / 72) ** 2 + (hy(k) / 54) ** 2 <= 1
def clear(k) = in_body(k) and hx(k) <= 40 and abs(hy(k)) >= 5 and abs(hx(k) - RIB_X) >= 5

SPINES = [(hx(k), hy(k)) for k in range(ROWS * COLS) if clear(k)]

def outline(grow=0) -> solid {
    body = Offset(Hull(Ellipse(center=(-10, 0), rx=80, ry=62), Circle(center=(105, 0), radius=6)), grow)
    long_mortise = tab_and_slot(part="slot", length=150 mm, thickness=t, tabs=3, tab=12 mm,
                                screw=0, rotation=0 deg, cx=-5 mm, cy=0 mm)
    short_mortise = tab_and_slot(part="slot", length=90 mm, thickness=t, tabs=2, tab=12 mm,
                                 screw=0, rotation=90 deg, cx=RIB_X * 1 mm, cy=0 mm)
    Rigid(self)
}

def rib(length=150 mm, tabs=3, halving_x=0 mm, from_top=true) -> solid {
    # drawn with the bottom shoulder on y = 0, the top shoulder on y = H; x across its length
    body = Rectangle(center=(0, H / 2), width=length, height=H + 2 * t)
    top_tabs = tab_and_slot(part="tab", length=length, thickness=t, tabs=tabs, tab=12 mm,
                            screw=0, rotation=0 deg, cx=0 mm, cy=H + t)
    bottom_tabs = tab_and_slot(part="tab", length=length, thickness=t, tabs=tabs, tab=12 mm,
                               screw=0, rotation=180 deg, cx=0 mm, cy=-t)
    if from_top {
        halving = cross_halving(depth=H / 2, thickness=t, rotation=0 deg, cx=halving_x, cy=H)
    } else {
        halving = cross_halving(depth=H / 2, thickness=t, rotation=180 deg, cx=halving_x, cy=0 mm)
    }
    Rigid(self)
}

assembly hedgehog {
    top = outline()
    base = outline(grow=8)
    # the long rib is drawn about its own middle (plate x -5), the short one about plate y 0
    long_rib = rib(length=150 mm, tabs=3, halving_x=(RIB_X + 5) * 1 mm, from_top=true)
    short_rib = rib(length=90 mm, tabs=2, halving_x=0 mm, from_top=false)

    hole spines {
        for p in SPINES {
            h = Circle(center=p, diameter=3.5)
        }
    }
    Rigid(spines, top)
    CutInto(spines, top)

    drawing face {
        eye_l = Circle(center=(58, 13), diameter=7, fill=true)
        eye_r = Circle(center=(58, -13), diameter=7, fill=true)
        nose = Circle(center=(104, 0), diameter=9, fill=true)
    }
    Rigid(face, top)
    CutInto(face, top)

    # flat on the sheet
    RightOf(base, top, gap=10)
    AlignTop(base, top)
    Below(long_rib, top, gap=10)
    AlignLeft(long_rib, top)
    RightOf(short_rib, long_rib, gap=10)
    AlignTop(short_rib, long_rib)

    # in 3D: base on the table, ribs standing on it, the top on the ribs
    Place(base, position=(0, 0, 0), face="up")
    Place(long_rib, position=(-5, 1.5, 3), face="front", up="up")
    Place(short_rib, position=(RIB_X - 1.5, 0, 3), face="right", up="up")
    Place(top, position=(0, 0, 33), face="up")

    assert top.body.bb.width == 201 mm, "201 nose to tail"
    assert top.body.bb.height == 124 mm, "124 wide"
    assert base.body.bb.width - top.body.bb.width == 16 mm, "base 8 mm bigger all round"
    assert len(SPINES) >= 50, "a good crowd of sticks"
    assert spines.h[0].diameter == 3.5 mm, "3.5 mm stick holes"
    assert distance(spines, top.long_mortise) >= 1.5 mm, "no stick hole over the long rib"
    assert distance(spines, top.short_mortise) >= 1.5 mm, "no stick hole over the short rib"
    assert long_rib.body.bb.width == 150 mm and short_rib.body.bb.width == 90 mm, "ribs 150 and 90"
    assert long_rib.halving.cut.bb.height + short_rib.halving.cut.bb.height == 30 mm, "halvings meet"
}
