# Camping: a flat-pack pot stand for a tea-light/alcohol stove, two 3 mm stainless plates that
# cross at right angles with a cross-halving joint (0.1 mm clearance). Each plate is a
# trapezoid 140 mm at the bottom, 100 mm at the top, 90 mm tall, with a half-round arch 50 mm
# across cut from the middle of the bottom edge (two feet). Plate A is slotted 45 mm down from
# the middle of its top edge, plate B 45 mm up from the middle of its bottom edge. "CAMP" 7 mm
# engraved on plate A, 32 mm left of the centre, 10 mm above the middle height.
# The two plates laid side by side 10 mm apart.

import "std/joints.aidl"

thickness 3 mm

assembly stand {
    solid a {
        body = Trapezoid(center=(0, 0), bottom_width=140, top_width=100, height=90)
        hole arch { c = Circle(center=(0, -45), diameter=50) }
        slot = cross_halving(depth=45 mm, thickness=3 mm, clearance=0.1 mm, cx=0 mm, cy=45 mm)
        drawing word { t = Text("CAMP", (-32, 10), size=7, valign="middle") }
    }
    solid b {
        body = Trapezoid(center=(160, 0), bottom_width=140, top_width=100, height=90)
        hole arch { c = Circle(center=(160, -45), diameter=50) }
        slot = cross_halving(depth=45 mm, thickness=3 mm, clearance=0.1 mm, rotation=180 deg,
                             cx=160 mm, cy=-45 mm)
    }
    RightOf(b.body, a.body, gap=10)
    AlignBottom(b.body, a.body)

    assert a.body.bb.width == 140 mm and a.body.bb.height == 90 mm, "plate 140 x 90"
    assert a.body.top_width == 100 mm, "top 100"
    assert a.slot.cut.bb.height == 45 mm, "A slotted 45"
    assert b.slot.cut.bb.height == 45 mm, "B slotted 45"
    assert a.slot.cut.bb.width == 3.1 mm, "slot 3 + 0.1"
    assert a.slot.cut.bb.top == a.body.bb.top, "A's slot from the top"
    assert b.slot.cut.bb.bottom == b.body.bb.bottom, "B's slot from the bottom"
    assert a.arch.c.diameter == 50 mm, "arch 50"
    assert b.body.bb.left - a.body.bb.right == 10 mm, "10 apart"
}
