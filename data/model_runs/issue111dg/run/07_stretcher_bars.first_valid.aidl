# Request (crafts): a stretcher frame for cross-stitch and needlepoint, 6 mm birch ply,
# four flat bars 30 mm wide glued into one 300 x 250 outer frame (a 240 x 190 opening) that
# lies flat. The corners are flat sliding dovetails, one tail 10 mm deep (10 degrees) on each
# end of the two side bars into a socket in the top and bottom bars. Engraved ticks along the
# inner edge of the top and bottom bars every 10 mm for centring the fabric: 4 mm long,
# 8 mm at every 50 mm from the centre, 25 ticks each across the 240 opening. The owner's
# name "ANNA" engraved in single-stroke letters, 8 mm, on the bottom bar, 80 mm left of
# the centre.

import "std/joints.aidl"

units mm
thickness 6 mm

W = 300 mm
H = 250 mm
bar = 30 mm
dv = 10 mm    # dovetail depth

def ticks_on(edge_y=0 mm, dir=1) -> drawing {
    for i in range(25) {
        k = Line((-120 + i * 10, edge_y),
                 (-120 + i * 10, edge_y + dir * (8 if (i - 12) % 5 == 0 else 4)))
    }
}

assembly frame {
    solid top {
        body = Rectangle(center=(0, H / 2 - bar / 2), width=W, height=bar)
        s1 = dovetail(part="socket", length=bar, depth=dv, tails=1, angle=10 deg,
                      cx=-W / 2 + bar / 2, cy=H / 2 - bar)
        s2 = dovetail(part="socket", length=bar, depth=dv, tails=1, angle=10 deg,
                      cx=W / 2 - bar / 2, cy=H / 2 - bar)
        marks = ticks_on(edge_y=H / 2 - bar, dir=1)
    }
    solid bottom {
        body = Rectangle(center=(0, -H / 2 + bar / 2), width=W, height=bar)
        s1 = dovetail(part="socket", length=bar, depth=dv, tails=1, angle=10 deg,
                      rotation=180 deg, cx=-W / 2 + bar / 2, cy=-H / 2 + bar)
        s2 = dovetail(part="socket", length=bar, depth=dv, tails=1, angle=10 deg,
                      rotation=180 deg, cx=W / 2 - bar / 2, cy=-H / 2 + bar)
        marks = ticks_on(edge_y=-H / 2 + bar, dir=-1)
        drawing name {
            n = Text("ANNA", position=(-80, -H / 2 + bar / 2 - 4), size=8, valign="middle")
        }
    }
    solid left {
        body = Rectangle(center=(-W / 2 + bar / 2, 0), width=bar, height=H - 2 * bar + 2 * dv)
        t1 = dovetail(part="tail", length=bar, depth=dv, tails=1, angle=10 deg,
                      cx=-W / 2 + bar / 2, cy=H / 2 - bar)
        t2 = dovetail(part="tail", length=bar, depth=dv, tails=1, angle=10 deg,
                      rotation=180 deg, cx=-W / 2 + bar / 2, cy=-H / 2 + bar)
    }
    solid right {
        body = Rectangle(center=(W / 2 - bar / 2, 0), width=bar, height=H - 2 * bar + 2 * dv)
        t1 = dovetail(part="tail", length=bar, depth=dv, tails=1, angle=10 deg,
                      cx=W / 2 - bar / 2, cy=H / 2 - bar)
        t2 = dovetail(part="tail", length=bar, depth=dv, tails=1, angle=10 deg,
                      rotation=180 deg, cx=W / 2 - bar / 2, cy=-H / 2 + bar)
    }

    assert right.body.bb.right - left.body.bb.left == 300 mm, "300 wide outside"
    assert top.body.bb.top - bottom.body.bb.bottom == 250 mm, "250 tall outside"
    assert right.body.bb.left - left.body.bb.right == 240 mm, "240 opening"
    assert top.body.bb.bottom - bottom.body.bb.top == 190 mm, "190 opening"
    assert top.body.bb.height == 30 mm and left.body.bb.width == 30 mm, "bars 30 wide"
    assert len(top.marks.k) == 25, "25 ticks"
    assert top.marks.k[1].start.x - top.marks.k[0].start.x == 10 mm, "ticks 10 apart"
    assert top.marks.k[12].start.x == top.body.center.x, "a tick on the centre"
    assert top.marks.k[12].length == 8 mm and top.marks.k[13].length == 4 mm, "8 / 4 mm ticks"
    assert bottom.name.n.position.x - bottom.body.center.x == -80 mm, "name 80 left of centre"
}
