# Garden: a hanging bird-feeder tray, 4 mm plywood. An open-top finger-jointed box 220 x 160 x
# 40 mm outside, 10 mm fingers. Drainage: 24 holes of 5 mm in 4 rows x 6 columns, 25 mm apart,
# the grid centred in the bottom. Hanging: two 6 mm holes in each end wall (left and right),
# 10 mm below its top edge, 100 mm apart, centred along the wall. "BIRD CAFE" engraved 12 mm
# high, centred on the front.
units mm
thickness 4 mm
import "std/joints.aidl"

assembly feeder {
    box = finger_box(length=220 mm, depth=160 mm, height=40 mm, thickness=4 mm, finger=10 mm, closed=false)

    hole drains {
        c = Circle(center=(0, 0), diameter=5)
        g = GridPattern(c, 4, 6, 25)
    }
    CenterInside(drains, box.bottom)
    CutInto(drains, box.bottom)

    # the left wall lies on its side in the net, its top edge at -x; the right's at +x
    hole hang_l {
        for k in range(2) {
            c = Circle(center=(0, -50 + 100 * k), diameter=6)
        }
    }
    hang_l.c[0].center.x == box.left.bb.left + 10 mm
    AlignCenterY(hang_l, box.left)
    CutInto(hang_l, box.left)

    hole hang_r {
        for k in range(2) {
            c = Circle(center=(0, -50 + 100 * k), diameter=6)
        }
    }
    hang_r.c[0].center.x == box.right.bb.right - 10 mm
    AlignCenterY(hang_r, box.right)
    CutInto(hang_r, box.right)

    drawing sign {
        word = Text("BIRD CAFE", (0, 0), size=12, valign="middle")
    }
    CenterInside(sign, box.front)
    CutInto(sign, box.front)

    assert box.front.bb.width == 220 mm and box.front.bb.height == 40 mm, "220 long, 40 high outside"
    assert box.left.bb.height == 160 mm and box.left.bb.width == 40 mm, "160 deep outside"
    assert len(drains.g) == 24, "24 drain holes"
    assert drains.c.diameter == 5 mm, "5 mm drain holes"
    assert drains.g[1].center.x - drains.g[0].center.x == 25 mm, "25 mm apart"
    assert drains.bb.width == 5 * 25 mm + 5 mm and drains.bb.height == 3 * 25 mm + 5 mm, "4 rows x 6 columns"
    assert abs(drains.bb.center_x - box.bottom.bb.center_x) < 0.001 mm, "grid centred in x"
    assert abs(drains.bb.center_y - box.bottom.bb.center_y) < 0.001 mm, "grid centred in y"
    assert hang_l.c[0].diameter == 6 mm, "6 mm hanging holes"
    assert hang_l.c[0].center.x - box.left.bb.left == 10 mm, "10 mm below the left wall's top edge"
    assert box.right.bb.right - hang_r.c[1].center.x == 10 mm, "10 mm below the right wall's top edge"
    assert hang_l.c[1].center.y - hang_l.c[0].center.y == 100 mm, "100 mm apart"
    assert sign.word.size == 12 mm, "BIRD CAFE 12 mm"
}
