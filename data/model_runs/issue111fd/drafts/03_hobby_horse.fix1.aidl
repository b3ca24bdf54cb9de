# Request (toys): a hobby horse head for a child, 300 mm tall, laminated from four layers of
# 6 mm poplar ply (24 mm thick) on a 24 x 24 mm square batten stick. The head faces the rider's
# left: a curved profile with a pointed ear, a muzzle and an 80 mm wide neck. The two inner
# layers have a 24 mm wide channel running 130 mm up from the neck's bottom edge, centred on the
# neck, for the batten; the two outer layers have two 6.4 mm bolt holes (M6) on the channel's
# centre line, 40 and 100 mm up, to bolt the batten through. All four layers have a 10 mm rein
# hole at the corner of the mouth. The outer layers are engraved: an almond eye with a filled
# pupil, a nostril, the mouth line, six mane tufts along the back of the neck and the name
# "DOBBIN" in filled serif letters 10 mm high reading up the neck. The far outer layer is the
# mirror image, so its engraving faces out too.

import "std/fasteners.aidl"

thickness 6 mm

T = 6 mm
NECK_X = 110 mm      # the neck's middle at its bottom edge

# the head's outline (facing -x), neck bottom corners sharp
# FIX after the first valid program: the ear's tip was a 12-degree spike (W0507, real: it burns
# away and is sharp for a child); now a rounded ear through two points, no corner there
PROFILE = [[70, 0], [150, 0], [162, 90], [152, 190], [128, 252], [138, 290], [128, 300], [108, 262],
           [70, 246], [30, 215], [0, 180], [-12, 152], [0, 132], [30, 128], [62, 140],
           [74, 100], [72, 40]]

def head_layer(side=1, outer=true) -> solid {
    body = Spline([(side * p[0], p[1]) for p in PROFILE], closed=true, corners=[0, 1])
    hole rein {
        c = Circle(center=(side * 38, 145), diameter=10)
    }
    if outer {
        for k in range(2) {
            bolt = clearance_hole(size=6, cx=side * NECK_X, cy=40 mm + k * 60 mm)
        }
        drawing face {
            eye = Ellipse(center=(side * 95, 215), rx=11, ry=6, rotation=side * -20 deg)
            pupil = Circle(center=(side * 97, 215), radius=4, fill=true)
            nostril = Ellipse(center=(side * 8, 162), rx=5, ry=3)
            mouth = Line((side * -4, 140), (side * 24, 137))
            for m in range(6) {
                tuft = Spline([(side * 148, 20 + m * 30), (side * 138, 34 + m * 30),
                               (side * 143, 48 + m * 30)])
            }
            name = Text("DOBBIN", position=(side * 112, 150), size=10, font="serif:Bold",
                        valign="middle", rotation=90 deg, fill=true)
        }
    } else {
        hole channel {
            r = Rectangle(center=(side * NECK_X, 64.5), width=24, height=131)
        }
    }
}

assembly hobby_horse {
    near = head_layer(side=1, outer=true)
    inner_a = head_layer(side=1, outer=false)
    inner_b = head_layer(side=1, outer=false)
    far = head_layer(side=-1, outer=true)
    # stacked along y, the near face at y = 0 looking front, the far one looking back
    Place(near, position=(0, T, 0), face="front", up="up")
    Place(inner_a, position=(0, 2 * T, 0), face="front", up="up")
    Place(inner_b, position=(0, 3 * T, 0), face="front", up="up")
    Place(far, position=(0, 3 * T, 0), face="back", up="up")

    # flat on the sheet, in a row
    RightOf(inner_a, near, gap=8)
    AlignBottom(inner_a, near)
    RightOf(inner_b, inner_a, gap=8)
    AlignBottom(inner_b, inner_a)
    RightOf(far, inner_b, gap=8)
    AlignBottom(far, inner_b)

    assert near.body.points[6].y - near.body.points[0].y == 300 mm, "300 mm tall to the ear tip"
    assert near.body.points[1].x - near.body.points[0].x == 80 mm, "neck 80 wide"
    assert inner_a.channel.r.width == 24 mm, "channel 24 wide for the batten"
    assert inner_a.channel.r.bb.top - inner_a.body.points[0].y == 130 mm, "channel 130 up"
    assert near.bolt[1].c.center.y - near.bolt[0].c.center.y == 60 mm, "bolts 40 and 100 up"
    assert near.bolt[0].c.center.y - near.body.points[0].y == 40 mm, "first bolt 40 up"
    assert near.rein.c.diameter == 10 mm, "rein hole 10 mm"
    assert len(near.face.tuft) == 6, "six mane tufts"
    assert distance(near.face.name, near.bolt) >= 3 mm, "name clear of the bolt holes"
    assert distance(near.face.name, near.face.eye) >= 3 mm, "name clear of the eye"
}
