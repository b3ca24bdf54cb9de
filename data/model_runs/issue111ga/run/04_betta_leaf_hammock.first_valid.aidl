# Request: a leaf hammock for a betta (Siamese fighting fish) to rest on near the surface,
# cut from 3 mm cast acrylic (kerf 0.1 mm), solvent-welded. The leaf is 70 mm from its
# straight 30 mm base to a pointed tip and 40 mm across at its widest, with an engraved
# midrib and four pairs of side veins. Its base has two 8 mm tabs that go through two slots
# (0.1 mm clearance) 10 mm above the bottom of a 24 x 100 mm stem with a rounded top; the
# stem hangs on an aquarium suction cup by a keyhole near its top (7 mm head, 3.5 mm slot,
# 6 mm long, pointing up), so the leaf stands straight out from the glass.

import "std/joints.aidl"
import "std/plates.aidl"

t = 3 mm
thickness t
kerf 0.1 mm

leaf_len = 70 mm
leaf_w = 40 mm
base_w = 30 mm
stem_w = 24 mm
stem_h = 100 mm
tab = 8 mm
slot_y = 10 mm

half = [(0, 0), (base_w / 2, 0), (19, -12), (leaf_w / 2, -25), (16, -45), (8, -60),
        (0, -leaf_len)]

assembly hammock {
    solid leaf {
        outline = Spline(mirror(half, about="y"), closed=true, corners=[1, 6, 11])
        j = tab_and_slot(part="tab", length=base_w, thickness=t, tabs=2, tab=tab, screw=0,
                         cx=0 mm, cy=0 mm)
        drawing veins {
            midrib = Line((0, -6), (0, -62))
            for k in range(4) {
                vl = Line((0, -12 - 11 * k), (-11 + k, -20 - 12 * k))
                vr = Line((0, -12 - 11 * k), (11 - k, -20 - 12 * k))
            }
        }
    }

    solid stem {
        body = RoundedRectangle(corner=(-stem_w / 2, 0), opposite=(stem_w / 2, stem_h),
                                corner_radii=[stem_w / 2, stem_w / 2, 0, 0])
        hang = keyhole(head=7 mm, slot_width=3.5 mm, length=6 mm, direction=90 deg,
                       cx=0 mm, cy=stem_h - 20 mm)
        j = tab_and_slot(part="slot", length=base_w, thickness=t, tabs=2, tab=tab, screw=0,
                         clearance=0.1 mm, cx=0 mm, cy=slot_y)
    }

    # flat on the sheet: the stem to the right of the leaf
    RightOf(stem, leaf, gap=5)
    AlignTop(stem, leaf)

    # assembled: the stem upright against the glass (y 0 to 3), the leaf level, its tabs
    # through the stem's slots
    Place(stem, position=(0, t, 0), face="front", up="up")
    Place(leaf, position=(0, t, slot_y - t / 2), face="up")

    # the request's numbers
    assert leaf.outline.points[0].y - leaf.outline.points[6].y == 70 mm, "70 mm base to tip"
    assert leaf.outline.points[3].x - leaf.outline.points[9].x == 40 mm, "40 mm across"
    assert leaf.outline.points[1].x - leaf.outline.points[11].x == 30 mm, "a 30 mm base"
    assert len(leaf.j.gap) == 3, "two tabs"
    assert len(stem.j.slot) == 2, "two slots"
    assert stem.j.slot[0].bb.width == 8.1 mm and stem.j.slot[0].bb.height == 3.1 mm,
        "slots 0.1 mm over the 8 mm tab and 3 mm sheet"
    assert stem.body.bb.width == 24 mm and stem.body.bb.height == 100 mm, "a 24 x 100 stem"
    assert stem.j.slot[0].bb.center_y - stem.body.bb.bottom == 10 mm, "slots 10 mm up"
    assert stem.body.bb.top - stem.hang.bb.top >= 5 mm, "the keyhole stays inside the stem"
    assert distance(leaf.veins, leaf.j) >= 1 mm, "the veins stop short of the tabs"
}
