# Two-piece serving board (kitchen): 400 x 250 mm, R15 outer corners, 6 mm plywood, cut as two
# halves (each fits a 300 mm bed) locked by a sliding dovetail across the middle: 4 tails,
# 12 mm deep, 10 deg, 0.1 mm clearance, the joint band centered on the board (x = -6 .. +6 mm);
# a handle slot in each end, 100 x 25 mm with round ends, running across the board, centered
# top to bottom, its outer edge 25 mm in from the board's end.

import "std/joints.aidl"

thickness 6 mm

L = 400 mm
W = 250 mm
band = 12 mm

assembly board {
    solid left {
        body = RoundedRectangle(bottom_left=(-L / 2, -W / 2), width=L / 2 + band / 2, height=W,
                                corner_radii=[15, 0, 0, 15])
        joint = dovetail(part="tail", length=W, depth=band, tails=4, angle=10 deg,
                         clearance=0.1 mm, rotation=-90 deg, cx=-band / 2, cy=0)
        hole handle {
            s = Slot(center=(-L / 2 + 25 + 12.5, 0), length=100, width=25, rotation=90)
        }
        Fixed(body)
    }
    solid right {
        body = RoundedRectangle(bottom_left=(-band / 2, -W / 2), width=L / 2 + band / 2, height=W,
                                corner_radii=[0, 15, 15, 0])
        joint = dovetail(part="socket", length=W, depth=band, tails=4, angle=10 deg,
                         clearance=0.1 mm, rotation=-90 deg, cx=-band / 2, cy=0)
        hole handle {
            s = Slot(center=(L / 2 - 25 - 12.5, 0), length=100, width=25, rotation=90)
        }
        Fixed(body)
    }
    AllowOverlap(left, right)   # the halves mate in the joint band

    assert right.body.bb.right - left.body.bb.left == 400 mm, "400 mm long"
    assert left.body.bb.height == 250 mm, "250 mm wide"
    assert left.body.bb.width <= 300 mm and right.body.bb.width <= 300 mm, "each half fits a 300 mm bed"
    assert left.body.bb.right - right.body.bb.left == 12 mm, "12 mm joint band"
    assert abs((left.body.bb.right + right.body.bb.left) / 2 - (left.body.bb.left + right.body.bb.right) / 2) < 0.01 mm, "band centered"
    assert left.handle.s.length == 100 mm and left.handle.s.width == 25 mm, "100 x 25 mm handle slots"
    assert left.handle.bb.left - left.body.bb.left == 25 mm, "left handle 25 mm in"
    assert right.body.bb.right - right.handle.bb.right == 25 mm, "right handle 25 mm in"
    assert abs(left.handle.bb.center_y - left.body.bb.center_y) < 0.01 mm, "handle centered"
}
