# Request: corner blocks for a strap (band) clamp, for gluing up picture frames.
# One corner block is a stack of three 6 mm birch-ply layers held by two M4 x 16
# countersunk screws with nuts (I cut four sets). Top and bottom layers: an L 60 x 60 mm
# with 20 mm wide arms; the frame's outside corner sits in the 90 degree inside corner of
# the L; the L's outside corner is rounded R15 so the 25 mm strap wraps smoothly.
# Middle layer: the same L but 3 mm in from the two outer edges (a 3 mm deep, 6 mm wide
# groove that keeps the strap on), its outside corner R12. An 8 mm relief hole at the
# inside corner keeps glue squeeze-out off the block. The two M4 holes sit on each arm's
# centre line, 40 mm from the outer edges; the top layer's are countersunk (9 mm heads),
# the bottom layer's are M4 nut traps, the middle layer's plain 4.5 mm clearance holes.
# "FRAME CLAMP" engraved on the top layer.

import "std/fasteners.aidl"

units mm
t = 6 mm
thickness t
kerf 0.15 mm

L = 60 mm        # the L's outer size
arm = 20 mm      # width of each arm
groove = 3 mm    # depth of the strap groove in the middle layer
r_out = 15 mm    # outside corner radius of the top and bottom layers
hole_at = 40 mm  # the M4 holes, from the outer edges along each arm
relief_d = 8 mm

def layer(inset=0 mm, kind="mid") -> solid {
    body = Polygon([(inset, inset), (L, inset), (L, arm), (arm, arm), (arm, L), (inset, L)])
    Fillet(body.points[0], r_out - inset)
    hole relief { c = Circle(center=(arm, arm), diameter=relief_d) }
    if kind == "bottom" {
        n1 = nut_trap(size=4, cx=hole_at, cy=arm / 2)
        n2 = nut_trap(size=4, cx=arm / 2, cy=hole_at, rotation=90 deg)
    } else {
        h1 = clearance_hole(size=4, cx=hole_at, cy=arm / 2)
        h2 = clearance_hole(size=4, cx=arm / 2, cy=hole_at)
        if kind == "top" {
            Countersink([h1, h2], diameter=9 mm)
            # FIX after the first valid program: W0505, the label ran across the countersunk
            # hole; two short lines in the square at the L's outer corner instead
            drawing label {
                w1 = Text("FRAME", position=(arm / 2 + 1 mm, arm / 2 + 2 mm), size=2.5, valign="middle")
                w2 = Text("CLAMP", position=(arm / 2 + 1 mm, arm / 2 - 2 mm), size=2.5, valign="middle")
            }
        }
    }
}

assembly corner_block {
    bottom = layer(inset=0 mm, kind="bottom")
    middle = layer(inset=groove, kind="mid")
    top = layer(inset=0 mm, kind="top")

    # flat on the sheet, side by side
    RightOf(middle, bottom, gap=5)
    AlignBottom(middle, bottom)
    RightOf(top, middle, gap=5)
    AlignBottom(top, middle)

    # stacked: bottom, middle, top
    Place(bottom, position=(0, 0, 0))
    Place(middle, position=(0, 0, t))
    Place(top, position=(0, 0, 2 * t))

    # the request's numbers
    assert top.body.bb.width == 60 mm and top.body.bb.height == 60 mm, "L is 60 x 60"
    assert bottom.body.bb.width == 60 mm, "bottom L is 60 wide"
    assert top.body.points[2].y - top.body.points[1].y == 20 mm, "arms 20 mm wide"
    assert middle.body.bb.width == 60 mm - 3 mm, "middle layer 3 mm in from the outer edge"
    assert middle.body.points[2].y - middle.body.points[1].y == 20 mm - 3 mm, "middle arm 17 mm"
    assert top.h1.c.diameter >= 4.3 mm and top.h1.c.diameter <= 4.8 mm, "M4 clearance"
    assert top.h1.c.center.x - top.body.bb.left == 40 mm, "hole 40 mm from the outer edge"
    assert top.h2.c.center.y - top.body.bb.bottom == 40 mm, "hole 40 mm from the outer edge"
    assert bottom.n1.hex.center.x - bottom.body.bb.left == 40 mm, "nut under the hole"
    assert top.relief.c.diameter == 8 mm, "8 mm relief hole"
    assert 3 * t == 18 mm and 16 mm < 3 * t, "M4 x 16 ends inside the stack"
}
