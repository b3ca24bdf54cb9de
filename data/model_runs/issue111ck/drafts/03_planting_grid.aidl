# Request (garden): a square-foot style planting grid that sits in a 400 x 300 mm window trough
# and marks out 4 x 3 squares of 100 mm. In 4 mm plywood, 30 mm tall slats: two long slats
# (400 mm) and three short slats (300 mm), cross-halved together: each long slat has three
# slots from its top edge at 100, 200 and 300 mm from its left end, each short slat two slots
# from its bottom edge at 100 and 200 mm, each slot half the slat's height (15 mm). The slats'
# top corners are chamfered 5 mm. Each slat is engraved with its name near its left end, 8 mm
# tall: "A" and "B" on the long slats, "1", "2", "3" on the short ones, so they go together
# in order.

import "std/joints.aidl"

thickness 4 mm

t = 4 mm
slat_h = 30 mm
square = 100 mm
long_len = 400 mm
short_len = 300 mm

def long_slat(label="A") -> solid {
    body = Rectangle(center=(0, 0), width=long_len, height=slat_h)
    for i in range(3) {
        h = cross_halving(depth=slat_h / 2, thickness=t, cx=-long_len / 2 + (i + 1) * square,
                          cy=slat_h / 2)
    }
    drawing mark {
        name = Text(label, position=(-long_len / 2 + 20, 0), size=8, valign="middle")
    }
    Chamfer([body.top_left, body.top_right], 5)
}

def short_slat(label="1") -> solid {
    body = Rectangle(center=(0, 0), width=short_len, height=slat_h)
    for i in range(2) {
        h = cross_halving(depth=slat_h / 2, thickness=t, rotation=180 deg,
                          cx=-short_len / 2 + (i + 1) * square, cy=-slat_h / 2)
    }
    drawing mark {
        name = Text(label, position=(-short_len / 2 + 20, 0), size=8, valign="middle")
    }
    Chamfer([body.top_left, body.top_right], 5)
}

assembly planting_grid {
    a = long_slat(label="A")
    b = long_slat(label="B")
    s1 = short_slat(label="1")
    s2 = short_slat(label="2")
    s3 = short_slat(label="3")

    Below(b, a, gap=6)
    Below(s1, b, gap=6)
    Below(s2, s1, gap=6)
    Below(s3, s2, gap=6)
    AlignLeft(b, a)
    AlignLeft(s1, a)
    AlignLeft(s2, a)
    AlignLeft(s3, a)

    # the request's numbers
    assert a.body.bb.width == 400 mm and s1.body.bb.width == 300 mm, "slat lengths"
    assert a.body.bb.height == 30 mm and s1.body.bb.height == 30 mm, "slats 30 mm tall"
    assert len(a.h) == 3 and len(s1.h) == 2, "3 slots per long slat, 2 per short"
    assert a.h[0].cut.bb.center_x - a.body.bb.left == 100 mm, "first long slot at 100 mm"
    assert a.h[2].cut.bb.center_x - a.body.bb.left == 300 mm, "last long slot at 300 mm"
    assert s1.h[1].cut.bb.center_x - s1.body.bb.left == 200 mm, "last short slot at 200 mm"
    assert a.body.bb.top - a.h[0].cut.bb.bottom == 15 mm, "long slots 15 mm deep"
    assert s1.h[0].cut.bb.top - s1.body.bb.bottom == 15 mm, "short slots 15 mm deep"
    assert a.mark.name.text == "A" and s3.mark.name.text == "3", "labels"
}
