# Request (pets): a planter for a 100 x 100 mm pot of cat grass, 3 mm plywood. An open-top
# finger-jointed box 116 x 116 mm outside, 80 mm tall (10 mm fingers), so 110 mm inside.
# The front panel is a cat: two pointed ears (36 mm wide at the base, centres 66 mm apart)
# rising 30 mm above the rim, with an engraved inner-ear line, and an engraved face: filled
# oval eyes (12 x 16 mm), a filled nose pointing down, a two-arc mouth and three whiskers each
# side. Back and sides plain; the bottom plain.

import "std/joints.aidl"

thickness 3 mm

param t = 3 mm, min = 2 mm, max = 6 mm
param side = 116 mm, min = 100 mm, max = 160 mm
param tall = 80 mm, min = 60 mm, max = 120 mm
param finger = 10 mm, min = 6 mm, max = 20 mm

assembly cat_grass_planter {
    bottom = finger_panel(width=side, height=side, thickness=t, finger=finger,
                          bottom="fingers", right="fingers", top="fingers", left="fingers")

    solid front {
        p = finger_panel(width=side, height=tall, thickness=t, finger=finger,
                         bottom="slots", right="fingers", top="flat", left="fingers")
        ear_l = Polygon([(-51, 39), (-15, 39), (-33, 70)])
        ear_r = Polygon([(15, 39), (51, 39), (33, 70)])
        drawing face {
            inner_l = Polyline([(-44, 42), (-33, 62), (-22, 42)])
            inner_r = Polyline([(22, 42), (33, 62), (44, 42)])
            eye_l = Ellipse(center=(-22, 10), rx=6, ry=8, fill=true)
            eye_r = Ellipse(center=(22, 10), rx=6, ry=8, fill=true)
            nose = Triangle(center=(0, -5), base=10, height=7, rotation=180 deg, fill=true)
            mouth_l = Arc(center=(-4, -12), radius=4, start_angle=180 deg, end_angle=360 deg)
            mouth_r = Arc(center=(4, -12), radius=4, start_angle=180 deg, end_angle=360 deg)
            for i in range(3) {
                wl = Line((-14, -8 - 4 * i), (-46, -2 - 9 * i))
                wr = Line((14, -8 - 4 * i), (46, -2 - 9 * i))
            }
        }
    }

    back = finger_panel(width=side, height=tall, thickness=t, finger=finger,
                        bottom="slots", right="fingers", top="flat", left="fingers")
    left = finger_panel(width=side, height=tall, thickness=t, finger=finger,
                        bottom="slots", right="slots", top="flat", left="slots")
    right = finger_panel(width=side, height=tall, thickness=t, finger=finger,
                         bottom="slots", right="slots", top="flat", left="slots")

    # flat on the sheet: bottom, then front and back to its right, the sides above them
    RightOf(front, bottom, gap=6)
    AlignBottom(front, bottom)
    RightOf(back, front, gap=6)
    AlignBottom(back, bottom)
    Above(left, front, gap=6)
    AlignLeft(left, front)
    RightOf(right, left, gap=6)
    AlignBottom(right, left)

    # assembled: an open box on its bottom, the cat facing the front
    Place(bottom, position=(0, 0, 0), face="up")
    Place(front, position=(0, -side / 2 + t, tall / 2), face="front", up="up")
    Place(back, position=(0, side / 2 - t, tall / 2), face="back", up="up")
    Place(left, position=(-side / 2 + t, 0, tall / 2), face="left", up="up")
    Place(right, position=(side / 2 - t, 0, tall / 2), face="right", up="up")

    # the request's numbers
    assert bottom.outline.width == 116 mm and bottom.outline.height == 116 mm
    assert front.p.outline.height == 80 mm and left.outline.height == 80 mm
    assert side - 2 * t == 110 mm, "110 mm inside"
    assert side - 2 * t >= 100 mm + 4 mm, "the pot goes in with room"
    assert front.ear_l.points[2].y - front.p.outline.bb.top == 30 mm
    assert front.ear_r.points[2].x - front.ear_l.points[2].x == 66 mm
    assert front.ear_l.points[1].x - front.ear_l.points[0].x == 36 mm
    assert front.face.eye_l.bb.width == 12 mm and front.face.eye_l.bb.height == 16 mm
    assert len(front.face.wl) == 3 and len(front.face.wr) == 3
    # the whiskers stay clear of the finger cuts on the sides
    assert front.face.wr[2].bb.right <= front.p.outline.bb.right - t - 3 mm
}
