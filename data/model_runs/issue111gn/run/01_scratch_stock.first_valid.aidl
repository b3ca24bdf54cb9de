# Request (workshop): a scratch stock for beading chair rails. Two L-shaped cheeks of 6 mm
# birch ply, each 150 mm long and 70 mm tall overall: a 150 x 50 body with a fence leg 40 mm
# wide dropping 20 mm below it at one end. A piece of 0.8 mm card scraper is clamped between
# the cheeks against the fence's inner edge by two M5 bolts 60 mm apart, 45 mm up, either side
# of the blade (at 25 and 85 mm from the fence end). A 22 mm finger hole centred 125 mm from the
# fence end. Outer corners R6; the inner corner of the L stays sharp. Cheek A takes M5 flat
# heads (countersunk 10 mm); cheek B is drawn as its mirror image (wing nuts, plain holes).
# Each outer face is engraved "SCRATCH STOCK" and a 0-15 mm depth scale (a tick every mm,
# long every 5 mm, numbers 0 5 10 15) down the fence's inner edge, to set the blade's reach.

units mm
thickness 6 mm
import "std/fasteners.aidl"

def cheek(hand=1, sunk=false) -> solid {
    body = Rectangle(center=(hand * 75, 45), width=150, height=50)
    fence = Rectangle(center=(hand * 20, 10), width=40, height=20)
    b1 = clearance_hole(size=5, cx=hand * 25, cy=45)
    b2 = clearance_hole(size=5, cx=hand * 85, cy=45)
    if sunk {
        Countersink([b1, b2], diameter=10)
    }
    hole grip { c = Circle(center=(hand * 125, 45), diameter=22) }
    drawing marks {
        title = Text("SCRATCH STOCK", position=(hand * 80, 60), size=5, valign="middle")
        for d in range(16) {
            tick = Line((hand * (40 - (5 if d % 5 == 0 else 3)), 20 - d), (hand * 40, 20 - d))
        }
        for d in range(0, 16, 5) {
            num = Text(str(d), position=(hand * 31, 20 - d), size=2.5, anchor="end" if hand > 0 else "start", valign="middle")
        }
    }
    if hand > 0 {
        Fillet([body.top_left, body.top_right, body.bottom_right, fence.bottom_left], 6)
    } else {
        Fillet([body.top_left, body.top_right, body.bottom_left, fence.bottom_right], 6)
    }
}

assembly scratch_stock {
    a = cheek(hand=1, sunk=true)
    b = cheek(hand=-1, sunk=false)
    LeftOf(b, a, gap=10)
    AlignBottom(b, a)
    # face to face, the blade's plane at y = 0, fences together at the left
    Place(a, position=(0, 0, 0), face="front", up="up")
    Place(b, position=(0, 0, 0), face="back", up="up")

    assert a.bb.width == 150 mm, "150 mm long"
    assert a.bb.height == 70 mm, "70 mm tall overall"
    assert a.body.bb.bottom - a.fence.bb.bottom == 20 mm, "fence drops 20 mm"
    assert a.fence.bb.width == 40 mm, "fence leg 40 mm wide"
    assert distance(a.b1.c.center, a.b2.c.center) == 60 mm, "bolts 60 mm apart"
    assert a.b1.c.center.x - a.fence.bb.left == 25 mm, "first bolt 25 mm from the fence end"
    assert a.b1.c.center.y - a.fence.bb.bottom == 45 mm, "bolts 45 mm up"
    assert a.grip.c.diameter == 22 mm, "22 mm finger hole"
    assert a.grip.c.center.x - a.fence.bb.left == 125 mm, "finger hole 125 mm in"
    assert len(a.marks.tick) == 16, "ticks 0..15 mm"
    assert b.bb.width == 150 mm and b.bb.height == 70 mm, "B the same size"
}
