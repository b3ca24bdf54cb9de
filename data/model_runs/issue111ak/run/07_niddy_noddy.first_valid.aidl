# Crafts: a niddy noddy (a hand reel for winding yarn into skeins), 6 mm birch ply, two parts:
# - the shaft with its first arm cut in one piece as a T: the arm 300 mm long and 30 mm
#   wide across the shaft's left end, the shaft 35 mm wide;
# - the second arm, 300 x 30 mm, which crosses the shaft's right end at right angles to the
#   first arm (out of the sheet) by a glued cross-halving, 15 mm deep in each part;
# - each arm end has a U notch 8 mm wide for the yarn, its bottom 140 mm from the shaft's
#   axis; the arms' centres are spaced so that one wrap round the four notches is 2.0 m
#   (four legs of sqrt(L^2 + 2 x 140^2) each, L the arm-to-arm distance);
# - the outer corners of the arm ends rounded R5, the T's inside corners R6;
#   "2 M SKEIN" engraved 10 mm tall along the middle of the shaft.

units mm
thickness 6 mm

import "std/joints.aidl"

t = 6 mm
arm_len = 300 mm
arm_w = 30 mm
shaft_w = 35 mm
notch_w = 8 mm
notch_r = 140 mm      # notch bottom from the axis
wrap = 2000 mm
L = sqrt((wrap / 4) ** 2 - 2 * notch_r ** 2)   # arm centre to arm centre

def yarn_notches() -> hole {
    top = Slot(start=(0, notch_r + notch_w / 2), end=(0, arm_len / 2), width=notch_w)
    bottom = Slot(start=(0, -notch_r - notch_w / 2), end=(0, -arm_len / 2), width=notch_w)
}

assembly niddy_noddy {
    solid reel {
        arm = Rectangle(center=(0, 0), width=arm_w, height=arm_len)
        shaft = Rectangle(corner=(0, -shaft_w / 2), opposite=(L + arm_w / 2, shaft_w / 2))
        notches = yarn_notches()
        halving = cross_halving(depth=arm_w / 2, thickness=t, rotation=-90 deg,
                                cx=L + arm_w / 2, cy=0)
        drawing label {
            l = Text("2 M SKEIN", position=(L / 2, 0), size=10, valign="middle")
        }
        Fillet([arm.top_left, arm.top_right, arm.bottom_left, arm.bottom_right], 5)
        Fillet([[arm.right, shaft.top], [arm.right, shaft.bottom]], 6)
    }

    solid cross_arm {
        bar = Rectangle(center=(0, 0), width=arm_w, height=arm_len)
        notches = yarn_notches()
        halving = cross_halving(depth=arm_w / 2, thickness=t, rotation=90 deg,
                                cx=-arm_w / 2, cy=0)
        Fillet(bar, 5)
    }

    RightOf(cross_arm, reel, gap=15)
    AlignCenterY(cross_arm, reel)

    assert reel.arm.height == 300 mm and cross_arm.bar.height == 300 mm, "arms 300 long"
    assert reel.arm.width == 30 mm and cross_arm.bar.width == 30 mm, "arms 30 wide"
    assert reel.shaft.height == 35 mm, "shaft 35 wide"
    assert reel.halving.depth == 15 mm and cross_arm.halving.depth == 15 mm, "halvings 15 deep"
    assert reel.notches.top.width == 8 mm, "8 mm notches"
    assert reel.notches.top.bb.bottom - reel.arm.center.y == 140 mm, "notch bottom at 140"
    assert abs(4 * sqrt((reel.halving.cx - arm_w / 2 - reel.arm.center.x) ** 2 + 2 * (140 mm) ** 2)
               - 2000 mm) < 0.5 mm, "one wrap is 2.0 m"
    assert reel.bb.width <= 600 mm, "fits the 600 mm bed"
}
