# Request: "A set of 4 painter's pyramids to hold work up off the bench while I paint or
# varnish it. Each pyramid is two 6 mm plywood triangles, 80 mm across the base and 60 mm
# tall, that slot together crosswise: one is slotted 30 mm up from the middle of its base,
# the other 30 mm down from its tip (a 0.15 mm clearance so they push together by hand).
# Round the base corners r3 so they don't chip. Engrave the pair number (1-4) low on one side
# of each triangle so the matched halves stay together."

import "std/joints.aidl"

thickness 6 mm

param base_w = 80 mm, min = 50 mm, max = 150 mm
param tall = 60 mm, min = 40 mm, max = 120 mm
param fit = 0.15 mm, min = 0 mm, max = 0.4 mm

def piece(n=1, from_top=false) -> solid {
    tri = Triangle(center=(0, tall / 2), base=base_w, height=tall)
    if from_top {
        slot = cross_halving(depth=tall / 2, thickness=6 mm, clearance=fit, cx=0, cy=tall)
    } else {
        slot = cross_halving(depth=tall / 2, thickness=6 mm, clearance=fit, rotation=180 deg,
                             cx=0, cy=0)
    }
    drawing label {
        t = Text(str(n), position=(-base_w / 4, 6), size=6)
    }
    Fillet([tri.a, tri.b], 3)
}

assembly pyramids {
    for i in range(4) {
        a = piece(n=i + 1, from_top=false)
        b = piece(n=i + 1, from_top=true)
        RightOf(b, a, gap=4)
        AlignBottom(b, a)
        # stood up, crossed at right angles, one pyramid every 120 mm along x
        Place(a, rotation=(90 deg, 0, 0), position=(i * 120 mm, 3 mm, 0))
        Place(b, rotation=(90 deg, 0, 90 deg), position=(i * 120 mm - 3 mm, 0, 0))
    }
    # two pyramids to a row on the sheet
    RightOf(a[1], b[0], gap=4)
    AlignBottom(a[1], b[0])
    Below(a[2], a[0], gap=4)
    AlignLeft(a[2], a[0])
    RightOf(a[3], b[2], gap=4)
    AlignBottom(a[3], b[2])

    assert len(a) == 4 and len(b) == 4, "4 pyramids of two triangles"
    # FIX after the first valid program: W0405 (the box is read before the r3 corners round
    # it off; the requested 80 mm is the triangle's base as drawn): assert the base member
    assert a[0].tri.base == 80 mm, "80 mm across the base"
    assert a[0].tri.bb.height == 60 mm, "60 mm tall"
    assert a[0].slot.depth == 30 mm and b[0].slot.depth == 30 mm, "slots 30 mm each"
    assert a[0].slot.depth + b[0].slot.depth == 60 mm, "the two slots add up to the height"
}
