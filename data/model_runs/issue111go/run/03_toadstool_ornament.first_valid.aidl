# Request (garden): a toadstool to stand in a flower bed, cut from 6 mm exterior ply.
# Two silhouettes slotted together crosswise (a cross halving, 0.2 mm play) so it looks
# round from every side. The cap is a dome 180 mm wide and 80 mm tall with a gill rim
# bulging 12 mm under it; the stem is 120 mm tall, 40 mm wide under the cap and 55 mm at
# the ground. One piece carries on below the ground into a 100 mm stake, 20 mm wide, with
# a point; the other ends at the ground. 300 mm from the stake's tip to the cap's top.
# Spots engraved filled on both caps, to paint white, clear of the slots.

import "std/joints.aidl"

t = 6 mm
thickness t

ground = 100 mm       # the stake's length: the ground line above its tip
stem_h = 120 mm
cap_base = ground + stem_h
cap_h = 80 mm
cap_w = 180 mm
top = cap_base + cap_h
mid = (ground + top) / 2     # where the two halving slots meet

def toadstool(stake=false, spots=[]) -> solid {
    solid cap {
        dome = Intersect(Ellipse(center=(0, cap_base), rx=cap_w / 2, ry=cap_h),
                         Rectangle(center=(0, cap_base + cap_h / 2 + 1 mm), width=cap_w + 2 mm,
                                   height=cap_h + 2 mm))
        gills = Ellipse(center=(0, cap_base), rx=cap_w / 2, ry=12)
    }
    stem = Trapezoid(center=(0, ground + stem_h / 2), bottom_width=55, top_width=40,
                     height=stem_h)
    if stake {
        spike = Polygon([(-10, ground), (10, ground), (10, 20), (0, 0), (-10, 20)])
    }
    drawing paint {
        for s in spots {
            dot = Circle(center=(s[0], s[1]), radius=s[2], fill=true)
        }
    }
}

assembly toadstool_kit {
    # the staked piece: its slot comes down from the cap's top to the middle
    solid a {
        body = toadstool(stake=true, spots=[[-55, 250, 11], [-22, 278, 7], [30, 270, 9],
                                            [62, 245, 8], [-30, 236, 5], [20, 238, 5]])
        slot = cross_halving(depth=top - mid, thickness=t, clearance=0.2 mm, cx=0 mm, cy=top)
    }
    # the short piece: its slot comes up from the ground line to the middle
    solid b {
        body = toadstool(spots=[[-60, 242, 8], [-28, 268, 10], [25, 280, 6], [52, 256, 11],
                                [22, 236, 5], [-75, 228, 4]])
        slot = cross_halving(depth=mid - ground, thickness=t, clearance=0.2 mm,
                             rotation=180 deg, cx=0 mm, cy=ground)
    }
    RightOf(b, a, gap=8)
    AlignBottom(b.body.stem, a.body.stem)

    Place(a, position=(0, t / 2, 0), face="front", up="up")
    Place(b, position=(-t / 2, 0, 0), face="right", up="up")

    assert a.bb.top - a.bb.bottom == 300 mm, "300 mm from tip to top"
    assert a.body.cap.bb.width == 180 mm and a.body.cap.bb.top - a.body.cap.bb.bottom == 80 mm + 12 mm,
        "cap 180 wide, 80 tall over a 12 mm rim"
    assert a.body.stem.height == 120 mm and a.body.stem.top_width == 40 mm and
        a.body.stem.bottom_width == 55 mm
    assert a.body.stem.bb.bottom - a.bb.bottom == 100 mm, "100 mm stake"
    assert b.bb.bottom == a.body.stem.bb.bottom, "the short piece ends at the ground"
    assert a.slot.depth + b.slot.depth == top - ground, "the halvings meet"
    assert distance(a.body.paint, a.slot) >= 3 mm and distance(b.body.paint, b.slot) >= 3 mm,
        "spots clear of the slots"
}
