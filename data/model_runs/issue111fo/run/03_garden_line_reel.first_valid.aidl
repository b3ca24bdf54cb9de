# Request: a garden line reel for marking straight rows, in 6 mm exterior ply, on an M8 bolt.
# - Two cheeks, 140 mm discs: an M8 clearance hole in the middle, three 24 mm lightening
#   holes on a 90 mm circle (at 30, 150, 270 deg), three mortises for the drum bars at
#   35 mm radius (at 90, 210, 330 deg), across the radius; the outer cheek also has a 10 mm
#   hole for a dowel crank handle at 58 mm radius (at 90 deg).
# - Three drum bars, 100 mm between the cheeks, 20 mm wide, a 10 mm tenon at each end
#   through the cheeks.
# - The stake: 450 mm long overall, 40 mm wide, a 60 mm point at the bottom, a round top
#   (R20) with the M8 axle hole at its centre, "ROW LINE" engraved filled along it.
# - The tie-off peg: 250 mm long overall, 30 mm wide, a 50 mm point, a V notch at the top
#   8 mm wide and 12 mm deep for the string.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm

T = 6 mm
CHEEK_D = 140 mm
BAR_R = 35 mm
BAR_GAP = 100 mm     # between the cheeks
AXLE_Z = 430 mm      # the axle's height on the stake (its tip at 0)

def cheek(crank=false) -> solid {
    disc = Circle(center=(0, 0), diameter=CHEEK_D)
    axle = clearance_hole(size=8, cx=0 mm, cy=0 mm)
    hole light {
        for a in [30, 150, 270] {
            c = Circle(center=(45 * cos(a * 1 deg), 45 * sin(a * 1 deg)), diameter=24)
        }
    }
    for a in [90, 210, 330] {
        m = tab_and_slot(part="slot", length=20 mm, thickness=T, tabs=1, tab=10 mm, screw=0,
                         rotation=(a + 90) * 1 deg,
                         cx=BAR_R * cos(a * 1 deg), cy=BAR_R * sin(a * 1 deg))
    }
    if crank {
        hole handle {
            c = Circle(center=(0, 58), diameter=10)
        }
    }
}

def bar() -> solid {
    body = Rectangle(center=(0, 0), width=BAR_GAP + 2 * T, height=20)
    left_tab = tab_and_slot(part="tab", length=20 mm, thickness=T, tabs=1, tab=10 mm, screw=0,
                            rotation=90 deg, cx=-(BAR_GAP / 2 + T), cy=0 mm)
    right_tab = tab_and_slot(part="tab", length=20 mm, thickness=T, tabs=1, tab=10 mm, screw=0,
                             rotation=-90 deg, cx=BAR_GAP / 2 + T, cy=0 mm)
}

assembly line_reel {
    inner = cheek()
    outer = cheek(crank=true)
    for i in range(3) {
        bars = bar()
    }

    solid stake {
        shaft = Rectangle(bottom_left=(-20, 60), width=40, height=370)
        tip = Triangle(center=(0, 30), base=40, height=60, rotation=180 deg)
        top = Circle(center=(0, 430), radius=20)
        axle = clearance_hole(size=8, cx=0 mm, cy=430 mm)
        drawing label {
            t = Text("ROW LINE", position=(0, 240), size=16, font="sans:Bold", valign="middle",
                     rotation=90 deg, fill=true)
        }
    }

    solid peg {
        shaft = Rectangle(bottom_left=(-15, 50), width=30, height=200)
        tip = Triangle(center=(0, 25), base=30, height=50, rotation=180 deg)
        hole notch {
            v = Triangle(center=(0, 250 - 6 + 0.5), base=8, height=13, rotation=180 deg)
        }
    }

    # flat on the sheet
    RightOf(peg, stake, gap=10)
    AlignBottom(peg, stake)
    RightOf(inner, peg, gap=10)
    AlignTop(inner, stake)
    Below(outer, inner, gap=10)
    AlignLeft(outer, inner)
    for i in range(3) {
        AlignLeft(bars[i], bars[0])
    }
    RightOf(bars[0], inner, gap=10)
    AlignTop(bars[0], inner)
    Below(bars[1], bars[0], gap=10)
    Below(bars[2], bars[1], gap=10)

    # in 3D: the axle along +x at 430 up; the stake's face at x = 0, the reel beside it
    Place(stake, position=(0, 0, 0), face="left", up="up")
    Place(inner, position=(2, 0, AXLE_Z), face="right", up="up")
    Place(outer, position=(2 + T + BAR_GAP, 0, AXLE_Z), face="right", up="up")
    for i in range(3) {
        Place(bars[i], position=(2 + T + BAR_GAP / 2,
                                 (BAR_R - T / 2) * cos((90 + 120 * i) * 1 deg),
                                 AXLE_Z + (BAR_R - T / 2) * sin((90 + 120 * i) * 1 deg)),
              face=(0, cos((90 + 120 * i) * 1 deg), sin((90 + 120 * i) * 1 deg)),
              up=(0, -sin((90 + 120 * i) * 1 deg), cos((90 + 120 * i) * 1 deg)))
    }
    # the peg stands at the far end of the row
    Place(peg, position=(0, -400, 0), face="left", up="up")

    assert inner.disc.diameter == 140 mm, "140 mm cheeks"
    assert len(bars) == 3, "three drum bars"
    assert bars[0].body.bb.width - 2 * T == 100 mm, "100 mm between the cheeks"
    assert stake.bb.height == 450 mm, "stake 450 long"
    assert stake.bb.width == 40 mm, "stake 40 wide"
    assert stake.axle.c.center.y == stake.top.center.y, "axle at the round top's centre"
    assert peg.shaft.bb.top - peg.tip.bb.bottom == 250 mm, "peg 250 long"
    assert peg.tip.bb.height == 50 mm, "50 mm point"
    assert stake.tip.bb.height == 60 mm, "60 mm point"
    assert outer.handle.c.diameter == 10 mm, "10 mm crank hole"
    assert distance(outer.handle.c.center, outer.disc.center) == 58 mm, "crank at 58 mm"
    assert distance(inner.light.c[0].center, inner.disc.center) == 45 mm, "lightening holes on a 90 mm circle"
    assert peg.shaft.bb.top - peg.notch.v.bb.bottom >= 12 mm, "notch 12 deep"
}
