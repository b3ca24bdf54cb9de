# Request: a pretzel tree for an Oktoberfest party table, 6 mm ply, no glue needed.
# Two identical-looking boards cross-halved into an X (one slotted from the top, one
# from the bottom, the slots meeting halfway), each a 40 mm trunk standing 320 mm
# above the base with a 44 mm round knob on top (342 mm overall), and on each side
# three arms for the pretzels to hang on: 16 mm wide with round ends, at 90, 170 and
# 250 mm up, reaching 100, 80 and 60 mm out from the trunk's side, each ending in a
# 24 mm upturned tip so a pretzel cannot slide off. Each board has two 10 mm tenons
# into a round base 220 mm across; "PROST! ZUM WOHL!" engraved round the base
# (single-stroke, 10 mm letters on a 90 mm radius, over the top).

units mm
thickness 6 mm
import "std/joints.aidl"

T = 6 mm
TRUNK = 40 mm
TOP = 320 mm
KNOB = 44 mm
TIER = [90 mm, 170 mm, 250 mm]
REACH = [100 mm, 80 mm, 60 mm]
ARM_W = 16 mm
TIP = 24 mm
OVERALL = TOP + KNOB / 2

def board(from_top=true) -> solid {
    trunk = Rectangle(bottom_left=(-TRUNK / 2, -T), width=TRUNK, height=TOP + T)
    knob = Circle(center=(0, TOP), diameter=KNOB)
    for i in range(3) {
        arm = Slot(start=(TRUNK / 2, TIER[i]), end=(TRUNK / 2 + REACH[i], TIER[i]), width=ARM_W)
        tip = Slot(start=(TRUNK / 2 + REACH[i], TIER[i]), end=(TRUNK / 2 + REACH[i], TIER[i] + TIP),
                   width=ARM_W)
    }
    axis = Line((0, 0), (0, 100), construction=true)
    left_arms = Mirrored(arm, axis)
    left_tips = Mirrored(tip, axis)
    feet = tab_and_slot(part="tab", length=TRUNK, thickness=T, tabs=2, tab=10 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=-T)
    if from_top {
        halving = cross_halving(depth=OVERALL / 2, thickness=T, clearance=0.1 mm, cx=0 mm, cy=OVERALL)
    } else {
        halving = cross_halving(depth=OVERALL / 2, thickness=T, clearance=0.1 mm, rotation=180 deg,
                                cx=0 mm, cy=0 mm)
    }
}

assembly pretzel_stand {
    upper = board(from_top=true)
    lower = board(from_top=false)

    solid base {
        disc = Circle(center=(0, 0), diameter=220)
        for_upper = tab_and_slot(part="slot", length=TRUNK, thickness=T, tabs=2, tab=10 mm, screw=0,
                                 cx=0 mm, cy=0 mm)
        for_lower = tab_and_slot(part="slot", length=TRUNK, thickness=T, tabs=2, tab=10 mm, screw=0,
                                 rotation=90 deg, cx=0 mm, cy=0 mm)
        drawing motto {
            ring = Circle(center=(0, 0), radius=90, construction=true)
            t = Text("PROST! ZUM WOHL!", along=ring, size=10)
        }
    }

    RightOf(lower, upper, gap=10)
    AlignBottom(lower, upper)
    RightOf(base, lower, gap=10)
    AlignBottom(base, upper)

    Place(base, position=(0, 0, 0), face="up")
    Place(upper, position=(0, T / 2, T), face="front", up="up")
    Place(lower, position=(-T / 2, 0, T), face="right", up="up")

    assert upper.knob.bb.top - upper.trunk.bb.bottom - 6 mm == 342 mm, "342 mm overall"
    assert upper.trunk.width == 40 mm and upper.knob.diameter == 44 mm, "trunk 40, knob 44"
    assert upper.halving.depth + lower.halving.depth == 342 mm, "the slots meet halfway"
    assert len(upper.arm) == 3 and len(upper.left_arms) == 3, "three arms a side"
    assert upper.arm[0].end.x - upper.trunk.bb.right == 100 mm, "lowest arm reaches 100"
    assert upper.arm[2].end.x - upper.trunk.bb.right == 60 mm, "top arm reaches 60"
    assert upper.arm[1].start.y - upper.trunk.bb.bottom - 6 mm == 170 mm, "middle arm 170 up"
    assert upper.tip[0].end.y - upper.tip[0].start.y == 24 mm, "24 mm tips"
    assert base.disc.diameter == 220 mm, "base 220 across"
}
