# Gifts: a caddy for a set of 100 mm square coasters (a housewarming gift), 3 mm ply.
# An open-top finger-jointed box 110 x 110 mm outside and 50 mm tall (104 mm inside: 2 mm play
# each side), 10 mm fingers. The front has a round thumb scoop, a 50 mm circle centred on the
# middle of its top edge (25 mm deep), and "CHEERS" in sans Bold, 8 mm tall, filled engraving,
# centred, its baseline 10 mm above the box's bottom edge. The back has a heart-shaped opening
# (two R9 lobes 16 mm apart, point 21 mm below the lobes' centres) in its middle.
thickness 3 mm

import "std/joints.aidl"

param size = 110 mm, min = 80, max = 160
param tall = 50 mm, min = 30, max = 80

assembly caddy {
    box = finger_box(length=size, depth=size, height=tall, thickness=3 mm, finger=10 mm,
                     closed=false)

    hole scoop {
        c = Circle(center=(0, 0), diameter=50)
    }
    AlignCenterX(scoop, box.front)
    scoop.c.center.y == box.front.bb.top
    CutInto(scoop, box.front)

    drawing words {
        w = Text("CHEERS", (0, 0), size=8, font="sans:Bold", fill=true)
    }
    AlignCenterX(words, box.front)
    words.w.position.y == box.front.bb.bottom + 10
    CutInto(words, box.front)

    hole heart {
        left = Hull(Circle(center=(-8, 5), radius=9), Point(0, -16))
        right = Hull(Circle(center=(8, 5), radius=9), Point(0, -16))
    }
    CenterInside(heart, box.back)
    CutInto(heart, box.back)

    assert box.front.bb.width == 110 mm, "110 mm outside"
    assert box.front.bb.height == 50 mm, "50 mm tall"
    assert box.left.bb.height == 110 mm, "110 mm deep"
    assert scoop.c.diameter == 50 mm, "50 mm scoop"
    assert box.front.bb.top - scoop.bb.bottom == 25 mm, "scoop 25 mm deep"
}
