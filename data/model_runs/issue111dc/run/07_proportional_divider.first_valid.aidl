# Request: an artist's proportional divider from 3 mm acrylic, for enlarging drawings. Two
# identical arms 200 mm tip to tip, 16 mm wide, each end tapering to a point over 25 mm; a
# 4.5 mm slot along the middle of each arm for the M4 pivot bolt, its bolt centre travelling
# from 30 to 105 mm from tip A. Ratio marks engraved on one side of the slot: a tick where the
# pivot must sit for ratios 1, 1.5, 2, 3, 4 and 5 (pivot at 200 / (1 + ratio) from tip A),
# 2 mm long just outside a 10 mm washer (5.5 to 7.5 mm from the centre line), each numbered
# (2 mm figures) on the other side of the slot. A 10 mm acrylic washer (4.5 mm hole) sits
# under the wing nut, with two engraved index marks across its rim (top and bottom).

import "std/shapes.aidl"

thickness 3 mm

L = 200 mm
W = 16 mm
taper = 25 mm
ratios = [1, 1.5, 2, 3, 4, 5]
labels = ["1", "1.5", "2", "3", "4", "5"]
def pivot(r) = L / (1 + r)

def arm() -> solid {
    body = Polygon([(0, 0), (taper, W / 2), (L - taper, W / 2), (L, 0), (L - taper, -W / 2),
                    (taper, -W / 2)])
    hole track { s = Slot(start=(30, 0), end=(105, 0), width=4.5) }
    drawing scale {
        for i in range(len(ratios)) {
            tick = Line((pivot(ratios[i]), 5.5), (pivot(ratios[i]), 7.5))
            num = Text(labels[i], position=(pivot(ratios[i]), -7.5), size=2)
        }
    }
    Rigid(self)
}

assembly divider {
    arm_a = arm()
    arm_b = arm()
    cursor = washer(outer=10 mm, inner=4.5 mm)
    drawing marks {
        up = Line((0, 3.3), (0, 4.8))
        down = Line((0, -3.3), (0, -4.8))
    }
    CenterInside(marks, cursor)
    CutInto(marks, cursor)

    # on the sheet
    Below(arm_b, arm_a, gap=5)
    AlignLeft(arm_b, arm_a)
    RightOf(cursor, arm_a, gap=5)
    AlignCenterY(cursor, arm_a)

    # assembled closed, the pivot at ratio 2
    Place(arm_a, position=(0, 0, 0), face="up")
    Place(arm_b, position=(0, 0, 3), face="up")
    Place(cursor, position=(pivot(2), 0, 6), face="up")

    # the request's numbers
    assert arm_a.body.bb.width == 200 mm and arm_a.body.bb.height == 16 mm, "arms 200 x 16"
    assert arm_a.track.s.start.x - arm_a.body.bb.left == 30 mm, "slot from 30"
    assert arm_a.track.s.end.x - arm_a.body.bb.left == 105 mm, "slot to 105"
    assert arm_a.track.s.width == 4.5 mm, "slot 4.5"
    assert len(arm_a.scale.tick) == 6, "6 ratio marks"
    assert pivot(5) > 30 mm and pivot(1) < 105 mm, "every mark within the bolt's travel"
    assert arm_a.scale.tick[3].start.x - arm_a.body.bb.left == 50 mm, "ratio 3 at 50 mm"
    assert cursor.ring.diameter == 10 mm, "washer 10"
    assert arm_a.scale.num[0].bb.bottom > arm_a.body.bb.bottom + 0.3 mm, "figures inside the arm"
}
