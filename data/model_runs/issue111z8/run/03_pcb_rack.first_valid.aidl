# Electronics: a rack that stands circuit boards on edge to store or dry them,
# 3 mm acrylic. Bar 200 long x 40 tall; 9 board slots 1.8 mm wide and 15 mm deep
# from the top edge, 20 mm apart, centred on the bar. Two feet 60 long x 20 tall
# cross the bar 8 mm in from each end: cross-halving slots 3 mm wide, 10 mm up
# into the bar from its bottom edge and 10 mm down into each foot from the
# middle of its top edge (bar and feet stand flush on the bench).

units mm
thickness 3 mm

import "std/joints.aidl"

def foot() -> solid {
    body = Rectangle(center=(0, 0), width=60, height=20)
    notch = cross_halving(depth=10 mm, thickness=3 mm, cx=0 mm, cy=10 mm)
}

assembly rack {
    solid bar {
        body = Rectangle(center=(0, 0), width=200, height=40)
        hole slots {
            for i in range(9) {
                s = Rectangle(center=((i - 4) * 20, 20 - 7.5 + 0.5), width=1.8, height=16)
            }
        }
        left_x = cross_halving(depth=10 mm, thickness=3 mm, rotation=180 deg, cx=-92 mm, cy=-20 mm)
        right_x = cross_halving(depth=10 mm, thickness=3 mm, rotation=180 deg, cx=92 mm, cy=-20 mm)
    }
    f1 = foot()
    f2 = foot()
    Below(f1, bar, gap=10)
    AlignLeft(f1, bar)
    RightOf(f2, f1, gap=10)
    AlignCenterY(f2, f1)

    assert bar.body.bb.width == 200 mm and bar.body.bb.height == 40 mm, "bar 200 x 40"
    assert len(bar.slots.s) == 9, "9 board slots"
    assert bar.slots.s[0].width == 1.8 mm, "slots 1.8 wide"
    assert bar.body.bb.top - bar.slots.s[0].bb.bottom == 15 mm, "slots 15 deep"
    assert bar.slots.s[1].center.x - bar.slots.s[0].center.x == 20 mm, "slots 20 apart"
    assert bar.slots.bb.center_x == bar.body.bb.center_x, "slots centred"
    assert f1.body.bb.width == 60 mm and f1.body.bb.height == 20 mm, "feet 60 x 20"
    assert bar.left_x.bb.center_x - bar.body.bb.left == 8 mm, "foot 8 in from the end"
    assert bar.body.bb.right - bar.right_x.bb.center_x == 8 mm, "foot 8 in from the other end"
    assert bar.left_x.depth + f1.notch.depth == f1.body.bb.height, "flush on the bench"
}
