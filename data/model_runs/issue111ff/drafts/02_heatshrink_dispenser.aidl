# Request (electronics): a heat-shrink tubing dispenser for the bench, 3 mm ply. A
# finger-jointed box 180 x 90 x 80 mm outside with a lift-off lid. Reels of tubing sit on a
# 6 mm dowel through both sides (6.5 mm holes, 45 mm above the bottom, centred front to
# back). The front has a row of 7 pull-out holes, 22 mm apart and centred, their centres
# 40 mm above the bottom, one per tubing size 1.6, 2.4, 3.2, 4.8, 6.4, 9.5 and 12.7 mm, each
# hole 1.5 mm bigger than its tubing; each size is engraved 12 mm below its hole. The lid
# carries "HEAT SHRINK" in filled letters, 10 mm tall, centred.

units mm
thickness 3 mm

import "std/boxes.aidl"

sizes = [1.6, 2.4, 3.2, 4.8, 6.4, 9.5, 12.7]
pitch = 22 mm
row_h = 40 mm
axle_h = 45 mm

assembly dispenser {
    box = lid_box(length=180 mm, width=90 mm, height=80 mm, thickness=3 mm, finger=10 mm)

    hole pulls {
        for i in range(7) {
            c = Circle(center=(i * pitch, 0), diameter=sizes[i] * 1 mm + 1.5 mm)
        }
    }
    Rigid(pulls)
    pulls.c[3].center.x == box.body.front.bb.center_x
    pulls.c[0].center.y == box.body.front.bb.bottom + row_h
    CutInto(pulls, box.body.front)

    drawing sizes_label {
        for i in range(7) {
            t = Text(str(sizes[i]), position=(i * pitch, -12), size=4, valign="middle")
        }
    }
    Rigid(sizes_label)
    sizes_label.t[0].position.x == pulls.c[0].center.x
    sizes_label.t[0].position.y == pulls.c[0].center.y - 12 mm
    CutInto(sizes_label, box.body.front)

    hole axle_l { c = Circle(center=(0, 0), diameter=6.5) }
    axle_l.c.center.x == box.body.left.bb.right - axle_h
    AlignCenterY(axle_l, box.body.left)
    CutInto(axle_l, box.body.left)

    hole axle_r { c = Circle(center=(0, 0), diameter=6.5) }
    axle_r.c.center.x == box.body.right.bb.left + axle_h
    AlignCenterY(axle_r, box.body.right)
    CutInto(axle_r, box.body.right)

    drawing title {
        t = Text("HEAT SHRINK", position=(0, 0), size=10, font="sans:Bold", valign="middle",
                 fill=true)
    }
    CenterInside(title, box.lid)
    CutInto(title, box.lid)

    # the request's numbers
    assert len(pulls.c) == 7, "seven pull-out holes"
    assert pulls.c[6].center.x - pulls.c[0].center.x == 6 * 22 mm, "22 mm apart"
    assert pulls.c[2].diameter == 3.2 mm + 1.5 mm, "3.2 tubing: 4.7 hole"
    assert pulls.c[6].diameter == 12.7 mm + 1.5 mm, "12.7 tubing: 14.2 hole"
    assert pulls.c[0].center.y - box.body.front.bb.bottom == 40 mm, "row 40 above the bottom"
    assert box.body.front.bb.right - pulls.c[6].center.x == pulls.c[0].center.x - box.body.front.bb.left,
        "row centred"
    assert pulls.c[4].center.y - sizes_label.t[4].position.y == 12 mm, "labels 12 below"
    assert box.body.left.bb.right - axle_l.c.center.x == 45 mm, "axle 45 above the bottom (left)"
    assert axle_r.c.center.x - box.body.right.bb.left == 45 mm, "axle 45 above the bottom (right)"
    assert box.body.front.bb.width == 180 mm, "box 180 long"
    assert box.lid.bb.width == 180 mm and box.lid.bb.height == 90 mm, "lid 180 x 90"
}
