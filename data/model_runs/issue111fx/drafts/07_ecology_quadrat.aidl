# Request: a 0.5 m ecology quadrat for the school's field trips (0.25 m^2 inside), flat-packed:
# four strips of 6 mm ply, 580 mm long and 25 mm tall, standing on edge and joined at the
# corners by cross halvings (each slot 6 mm wide and half the strip, 12.5 mm, deep: the front
# and back strips slotted from the top, the side strips from the bottom), so the clear
# inside is exactly 500 x 500 mm. A string grid of 10 x 10 squares: nine 3 mm holes at 50 mm
# pitch in every strip, 8 mm up in the front and back strips and 14 mm up in the side strips,
# so the strings cross 6 mm apart. The front and back strips carry a centimetre scale along
# their top edge on the outside (3 mm ticks every 10 mm, 6 mm ticks every 50 mm, "10" ... "40"
# at the decimetres); the side strips "QUADRAT" and "0.25 m²" on the outside.

units mm
thickness 6 mm
import "std/joints.aidl"

t = 6 mm
strip_l = 580 mm
strip_h = 25 mm
cross = 250 mm + t / 2      # the crossing strip's middle, from the centre

def strip(kind="x") -> solid {
    body = Rectangle(corner=(-strip_l / 2, 0), opposite=(strip_l / 2, strip_h))
    if kind == "x" {
        h1 = cross_halving(depth=strip_h / 2, thickness=t, cx=-cross, cy=strip_h)
        h2 = cross_halving(depth=strip_h / 2, thickness=t, cx=cross, cy=strip_h)
    } else {
        h1 = cross_halving(depth=strip_h / 2, thickness=t, rotation=180 deg, cx=-cross, cy=0)
        h2 = cross_halving(depth=strip_h / 2, thickness=t, rotation=180 deg, cx=cross, cy=0)
    }
    hole strings {
        for i in range(9) {
            c = Circle(center=(-200 + i * 50, 8 if kind == "x" else 14), diameter=3)
        }
    }
    drawing marks {
        if kind == "x" {
            for i in range(1, 50) {
                tk = Line((-250 + i * 10, strip_h - 0.5), (-250 + i * 10, strip_h - 0.5 - (6 if i % 5 == 0 else 3)))
            }
            for k in range(1, 5) {
                n = Text(str(k * 10), position=(-250 + k * 100, 13.5), size=4)
            }
        } else {
            w1 = Text("QUADRAT", position=(-75, 18), size=5)
            w2 = Text("0.25 m²", position=(75, 18), size=5, font="sans")
        }
    }
}

assembly quadrat {
    front = strip(kind="x")
    back = strip(kind="x")
    right = strip(kind="y")
    left = strip(kind="y")

    # flat on the sheet: four strips one above the other
    Above(back, front, gap=5)
    Above(right, back, gap=5)
    Above(left, right, gap=5)
    AlignLeft(back, front)
    AlignLeft(right, front)
    AlignLeft(left, front)

    # on the grass: on edge, engraved faces outward
    Place(front, position=(0, -250, 0), face="front", up="up")
    Place(back, position=(0, 250, 0), face="back", up="up")
    Place(right, position=(250, 0, 0), face="right", up="up")
    Place(left, position=(-250, 0, 0), face="left", up="up")

    # the request's numbers
    assert front.body.width == 580 mm and front.body.height == 25 mm, "580 x 25 strips"
    assert front.h2.cut.bb.left - front.h1.cut.bb.right == 500 mm, "500 mm clear inside"
    assert right.h2.cut.bb.left - right.h1.cut.bb.right == 500 mm, "500 mm clear inside"
    assert front.h1.cut.bb.width == 6 mm, "6 mm slots"
    assert front.h1.cut.bb.height + right.h1.cut.bb.height == 25 mm, "the halvings add up"
    assert front.body.bb.top - front.h1.cut.bb.bottom == 12.5 mm, "front slotted from the top"
    assert right.h1.cut.bb.top - right.body.bb.bottom == 12.5 mm, "sides slotted from the bottom"
    assert len(front.strings.c) == 9 and len(right.strings.c) == 9, "nine string holes"
    assert front.strings.c[0].center.x - front.h1.cut.bb.right == 50 mm, "first string 50 in"
    assert front.strings.c[1].center.x - front.strings.c[0].center.x == 50 mm, "50 mm pitch"
    assert front.strings.c[0].diameter == 3 mm, "3 mm holes"
    assert front.strings.c[0].center.y - front.body.bb.bottom == 8 mm, "front strings 8 up"
    assert right.strings.c[0].center.y - right.body.bb.bottom == 14 mm, "side strings 14 up"
    assert len(front.marks.tk) == 49, "49 ticks between the inner faces"
    assert len(front.marks.n) == 4, "10 20 30 40"
    assert distance(front.marks, front.strings) >= 2 mm, "scale clear of the holes"
    assert distance(right.marks, right.strings) >= 2 mm, "words clear of the holes"
    assert distance(front.marks, front.h1) >= 2 mm and distance(front.marks, front.h2) >= 2 mm,
        "scale clear of the halvings"
}
