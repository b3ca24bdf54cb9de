# Request: a storage box for twelve 70 mm Christmas baubles, from 3 mm plywood. A finger-
# jointed tray 330 x 250 mm and 90 mm tall outside, split into 3 rows x 4 columns of cells by
# cross-halved dividers 60 mm high (low enough to reach in). A lift-off lid: a 330 x 250 mm
# top plate with a locating plate glued under it that fits inside the walls with 0.3 mm
# clearance all round. Two 22 mm finger holes through lid and locating plate, 25 mm in from
# the short ends. The lid is engraved, filled: a five-pointed star 50 mm across above
# "CHRISTMAS" (bold serif, 22 mm) and "ORNAMENTS" (bold serif, 14 mm) under it.

import "std/boxes.aidl"

thickness 3 mm

t = 3 mm
box_l = 330 mm
box_w = 250 mm
box_h = 90 mm
fit = 0.3 mm
finger_d = 22 mm
finger_in = 25 mm

assembly ornament_box {
    tray = divider_tray(length=box_l, width=box_w, height=box_h, rows=3, cols=4,
                        thickness=t, finger=12 mm, clearance=fit, divider_height=60 mm)

    solid lid {
        plate = Rectangle(center=(0, 0), width=box_l, height=box_w)
        for side in [-1, 1] {
            hole grip { c = Circle(center=(side * (box_l / 2 - finger_in), 0),
                                   diameter=finger_d) }
        }
        drawing decor {
            star = Star(center=(0, 55 mm), points=5, outer_radius=25 mm, inner_radius=10 mm,
                        fill=true)
            word = Text("CHRISTMAS", position=(0, 0), size=22 mm, font="serif:Bold",
                        valign="middle", fill=true)
            word2 = Text("ORNAMENTS", position=(0, -35 mm), size=14 mm, font="serif:Bold",
                         valign="middle", fill=true)
        }
    }
    solid lip {
        plate = Rectangle(center=(0, 0), width=box_l - 2 * t - 2 * fit,
                          height=box_w - 2 * t - 2 * fit)
        for side in [-1, 1] {
            hole grip { c = Circle(center=(side * (box_l / 2 - finger_in), 0),
                                   diameter=finger_d) }
        }
    }
    RightOf(lid, tray, gap=15)
    AlignTop(lid, tray)
    Below(lip, lid, gap=15)
    AlignLeft(lip, lid)
    Place(lid, position=(0, 0, box_h), face="up")
    Place(lip, position=(0, 0, box_h - t), face="up")

    assert tray.rows * tray.cols == 12, "twelve cells"
    assert lid.plate.width == 330 mm and lid.plate.height == 250 mm, "lid 330 x 250"
    assert tray.length == 330 mm and tray.width == 250 mm and tray.height == 90 mm,
        "tray 330 x 250 x 90 outside"
    assert (box_l - 2 * t) - lip.plate.width == 2 * 0.3 mm, "lip 0.3 mm clear all round"
    assert lid.grip[0].c.bb.left - lid.plate.bb.left == 25 mm - 11 mm,
        "finger holes centred 25 mm in"
    assert lid.decor.star.bb.height <= 50 mm, "star 50 mm"
}
