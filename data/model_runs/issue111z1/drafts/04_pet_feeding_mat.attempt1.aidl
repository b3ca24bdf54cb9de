# Pets: a cat's feeding placemat, 3 mm cast acrylic, 360 x 240 mm with R20 corners.
# Two engraved bowl rings 140 mm across, centred 90 mm left and right of the middle, 15 mm above
# the mat's centre line. Between them a trail of three engraved paw prints walking up (each: a
# pad 14 x 12 mm and four 5.6 mm toes), 40 mm apart, alternating 6 mm left and right.
# The cat's name "MILO" in sans Bold, 24 mm tall, filled engraving, centred 25 mm above the
# bottom edge (its middle).
thickness 3 mm

param mat_w = 360 mm, min = 280, max = 500
param mat_h = 240 mm, min = 180, max = 320
param bowl_d = 140 mm, min = 100, max = 180
param name = "MILO"

def paw(x=0 mm, y=0 mm) -> drawing {
    pad = Ellipse(center=(x, y), rx=7, ry=6)
    toe_a = Circle(center=(x - 8, y + 9), diameter=5.6)
    toe_b = Circle(center=(x - 3, y + 13), diameter=5.6)
    toe_c = Circle(center=(x + 3, y + 13), diameter=5.6)
    toe_d = Circle(center=(x + 8, y + 9), diameter=5.6)
}

solid mat {
    body = RoundedRectangle(center=(0, 0), width=mat_w, height=mat_h, corner_radius=20)

    drawing bowls {
        left = Circle(center=(-90, 15), diameter=bowl_d)
        right = Circle(center=(90, 15), diameter=bowl_d)
    }
    drawing trail {
        p1 = paw(x=-6 mm, y=-40 mm)
        p2 = paw(x=6 mm, y=0 mm)
        p3 = paw(x=-6 mm, y=40 mm)
    }
    drawing label {
        word = Text(name, (0, -mat_h / 2 + 25), size=24, font="sans:Bold", fill=true,
                    valign="middle")
    }

    assert body.width == 360 mm and body.height == 240 mm, "360 x 240 mat"
    assert bowls.left.diameter == 140 mm, "140 mm bowl rings"
    assert bowls.right.center.x - bowls.left.center.x == 180 mm, "bowls 90 mm each side"
    assert bowls.left.center.y - body.center.y == 15 mm, "bowls 15 mm above the centre line"
    assert trail.p2.pad.center.y - trail.p1.pad.center.y == 40 mm, "paws 40 mm apart"
    assert label.word.center.y - body.bb.bottom == 25 mm, "name's middle 25 mm above the bottom"
}
