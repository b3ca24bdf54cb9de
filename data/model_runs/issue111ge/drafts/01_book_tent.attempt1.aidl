# Request (home): a bedside "book tent" - a rest you lay an open paperback on, face down, to keep
# the page without cracking the spine. 3 mm birch ply, an egg-crate of 5 parts:
# - three identical A-shaped ribs, 150 mm wide at the base and 50 mm tall, apex rounded R8, the
#   two base tips rounded R3, a 60 x 18 half-ellipse arch cut from the middle of the bottom edge;
#   each rib has two halving slots from the bottom edge, 10 mm deep, at 40 mm each side of centre;
# - two stringers 180 x 20 mm, with halving slots 10 mm deep from the top edge at 15, 90 and
#   165 mm along (so the ribs stand 75 mm apart);
# - the front rib has "KEEP MY PAGE" engraved (5 mm letters) above the arch.
# Halvings get 0.1 mm clearance so they push together by hand.

import "std/joints.aidl"

thickness 3 mm

param clear = 0.1 mm, min = 0 mm, max = 0.3 mm

rib_w = 150 mm
rib_h = 50 mm
halving = 10 mm
slot_x = 40 mm
str_len = 180 mm
str_h = 20 mm
rib_at = [15 mm, 90 mm, 165 mm]

def rib(label="") -> solid {
    tri = Polygon([(-75, 0), (75, 0), (0, 50)])
    Fillet(tri.points[2], 8 mm)
    Fillet(tri.points[0], 3 mm)
    Fillet(tri.points[1], 3 mm)
    hole arch {
        a = Ellipse(center=(0, 0), rx=30, ry=18)
    }
    left = cross_halving(depth=10 mm, thickness=3 mm, clearance=clear, rotation=180 deg, cx=-40 mm, cy=0 mm)
    right = cross_halving(depth=10 mm, thickness=3 mm, clearance=clear, rotation=180 deg, cx=40 mm, cy=0 mm)
    if label != "" {
        drawing words {
            t = Text(label, position=(0, 27), size=5)
        }
    }
}

def stringer() -> solid {
    bar = Rectangle(bottom_left=(0, 0), width=180, height=20)
    s0 = cross_halving(depth=10 mm, thickness=3 mm, clearance=clear, cx=15 mm, cy=20 mm)
    s1 = cross_halving(depth=10 mm, thickness=3 mm, clearance=clear, cx=90 mm, cy=20 mm)
    s2 = cross_halving(depth=10 mm, thickness=3 mm, clearance=clear, cx=165 mm, cy=20 mm)
}

assembly book_tent {
    front = rib(label="KEEP MY PAGE")
    middle = rib()
    back = rib()
    left = stringer()
    right = stringer()

    # flat on the sheet: ribs in a row, stringers below them
    RightOf(middle, front, gap=5)
    AlignBottom(middle, front)
    RightOf(back, middle, gap=5)
    AlignBottom(back, middle)
    Below(left, front, gap=5)
    AlignLeft(left, front)
    Below(right, left, gap=5)
    AlignLeft(right, left)

    # in 3D: ribs stand across the spine (their faces to the front), stringers along it
    Place(front, position=(0, 15 + 1.5, 0), face="front", up="up")
    Place(middle, position=(0, 90 + 1.5, 0), face="front", up="up")
    Place(back, position=(0, 165 + 1.5, 0), face="front", up="up")
    Place(left, position=(-40 - 1.5, 0, 0), face="right", up="up")
    Place(right, position=(40 - 1.5, 0, 0), face="right", up="up")

    # the request's numbers
    assert front.tri.bb.width == 150 mm, "rib 150 wide"
    assert front.tri.bb.height == 50 mm, "rib 50 tall"
    assert left.bar.bb.width == 180 mm and left.bar.bb.height == 20 mm, "stringer 180 x 20"
    assert front.left.depth + left.s0.depth == 20 mm, "halvings add up to the stringer height"
    assert left.s1.cx - left.s0.cx == 75 mm and left.s2.cx - left.s1.cx == 75 mm, "ribs 75 apart"
    assert front.right.cx - front.left.cx == 80 mm, "stringers 80 apart"
    # the stringer stays under the rib's slope where they cross (slope height at x = 41.5)
    assert 50 mm * (1 - 41.5 / 75) > 20 mm, "stringer hidden under the slope"
    # the label sits above the arch and inside the slopes
    assert front.words.bb.bottom >= 18 mm + 3 mm, "label clear of the arch"
    assert front.words.bb.width <= 2 * 75 mm * (1 - front.words.bb.top / 50 mm) - 6 mm, "label inside the slopes"
}
