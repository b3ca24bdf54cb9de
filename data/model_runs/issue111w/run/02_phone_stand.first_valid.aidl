# Office: a flat-pack desk phone stand of three 3 mm pieces, no glue. Two side
# profiles: a foot 102 mm long (x -12 .. 90), a front lip 16 mm high and 8 mm
# thick, the phone's ledge 8 mm above the desk from x 40 to 82, the back rest
# leaning up to a top 95 mm high at x 0 (a 12 mm wide top). One cross bar
# 76 x 20 mm joins the sides 60 mm apart (centre to centre) by cross halving:
# each side has a 10 mm slot up from its bottom edge at x 20, the bar two 10 mm
# slots down from its top edge, 0.1 mm clearance (3.1 mm wide).

import "std/joints.aidl"

thickness 3 mm
param apart = 60 mm, min = 50, max = 90
param clear = 0.1 mm, min = 0, max = 0.3

def side_profile() -> solid {
    outline = Polygon([(-12, 0), (90, 0), (90, 16), (82, 16), (82, 8), (40, 8), (0, 95), (-12, 92)])
    slot = cross_halving(depth=10 mm, thickness=3 mm, clearance=clear, rotation=180 deg, cx=20 mm, cy=0 mm)
}

assembly stand {
    left = side_profile()
    right = side_profile()
    solid bar {
        body = Rectangle(center=(0, 0), width=76, height=20)
        a = cross_halving(depth=10 mm, thickness=3 mm, clearance=clear, cx=-apart / 2, cy=10 mm)
        b = cross_halving(depth=10 mm, thickness=3 mm, clearance=clear, cx=apart / 2, cy=10 mm)
    }
    RightOf(right, left, gap=5)
    AlignBottom(right, left)
    Below(bar, left, gap=5)
    AlignLeft(bar, left)

    assert left.outline.bb.width == 102 mm, "foot 102 long"
    assert left.outline.bb.height == 95 mm, "top 95 high"
    assert bar.body.bb.width == 76 mm and bar.body.bb.height == 20 mm, "bar 76 x 20"
    assert left.slot.depth + bar.a.depth == 20 mm, "halvings add up to the bar's 20 mm"
    assert bar.b.cx - bar.a.cx == 60 mm, "sides 60 apart"
}
