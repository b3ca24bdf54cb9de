# Request: a magnetic hanger for an A1 poster (594 wide) in the office. Two rails, top and
# bottom; each rail is a front and a back strip of 3 mm ply, 614 x 24 with round ends, the
# poster clamped between them by six 10 x 3 mm disc magnets per strip (holes 10.2 mm, on a
# 110 mm pitch, symmetric about the middle). My laser bed is 600 x 400, so every strip is
# two halves of 307, locked at the middle by a sliding dovetail (one tail, 10 mm deep,
# 0.1 mm clearance). The top back strip has two hanging ears, 200 either side of the
# middle, each with a 5 mm cord hole.

import "std/joints.aidl"

units mm
thickness 3 mm

half = 307 mm          # half a strip, from the middle to a round end
strip_h = 24 mm
dt_depth = 10 mm
pitch = 110 mm
magnet_d = 10.2 mm
ear_x = 200 mm

def sgn(side) = -1 if side == "left" else 1

def strip_half(side="left", ear=false) -> solid {
    if side == "left" {
        bar = Rectangle(corner=(-(half - strip_h / 2), -strip_h / 2), opposite=(dt_depth, strip_h / 2))
        cap = Circle(center=(-(half - strip_h / 2), 0), radius=strip_h / 2)
        joint = dovetail(part="tail", length=strip_h, depth=dt_depth, tails=1,
                         rotation=-90 deg, cx=0 mm, cy=0 mm)
    } else {
        bar = Rectangle(corner=(0, -strip_h / 2), opposite=(half - strip_h / 2, strip_h / 2))
        cap = Circle(center=(half - strip_h / 2, 0), radius=strip_h / 2)
        joint = dovetail(part="socket", length=strip_h, depth=dt_depth, tails=1,
                         clearance=0.1 mm, rotation=-90 deg, cx=0 mm, cy=0 mm)
    }
    hole magnets {
        for i in range(3) {
            m = Circle(center=(sgn(side) * (pitch / 2 + i * pitch), 0), diameter=magnet_d)
        }
    }
    if ear {
        solid hanger {
            tab = Hull(Circle(center=(sgn(side) * ear_x, strip_h / 2 + 9 mm), radius=8),
                       Rectangle(center=(sgn(side) * ear_x, strip_h / 2 - 2 mm), width=30, height=4))
            hole cord { c = Circle(center=(sgn(side) * ear_x, strip_h / 2 + 9 mm), diameter=5) }
        }
    }
    assert len(magnets.m) == 3, "three magnets in each half"
    assert magnets.m[0].diameter == 10.2 mm, "10.2 mm magnet holes"
    assert distance(magnets, joint) >= 3 mm, "magnets clear of the dovetail"
}

assembly poster_hanger {
    top_back_left = strip_half(side="left", ear=true)
    top_back_right = strip_half(side="right", ear=true)
    top_front_left = strip_half(side="left")
    top_front_right = strip_half(side="right")
    bottom_back_left = strip_half(side="left")
    bottom_back_right = strip_half(side="right")
    bottom_front_left = strip_half(side="left")
    bottom_front_right = strip_half(side="right")

    # flat on the sheet: one row per strip, the halves side by side
    RightOf(top_back_right, top_back_left, gap=6)
    AlignBottom(top_back_right.bar, top_back_left.bar)
    Below(top_front_left, top_back_left, gap=6)
    AlignLeft(top_front_left, top_back_left)
    RightOf(top_front_right, top_front_left, gap=6)
    AlignBottom(top_front_right, top_front_left)
    Below(bottom_back_left, top_front_left, gap=6)
    AlignLeft(bottom_back_left, top_front_left)
    RightOf(bottom_back_right, bottom_back_left, gap=6)
    AlignBottom(bottom_back_right, bottom_back_left)
    Below(bottom_front_left, bottom_back_left, gap=6)
    AlignLeft(bottom_front_left, bottom_back_left)
    RightOf(bottom_front_right, bottom_front_left, gap=6)
    AlignBottom(bottom_front_right, bottom_front_left)

    # assembled: the poster in the plane y = 0, 841 tall; back strips behind it, front
    # strips in front, each rail over 12 mm of the poster's edge
    Place(top_back_left, position=(0, 3, 841 - 12 + strip_h / 2 - 12), face="front", up="up")
    Place(top_back_right, position=(0, 3, 841 - 12 + strip_h / 2 - 12), face="front", up="up")
    Place(top_front_left, position=(0, 0, 841 - 12 + strip_h / 2 - 12), face="front", up="up")
    Place(top_front_right, position=(0, 0, 841 - 12 + strip_h / 2 - 12), face="front", up="up")
    Place(bottom_back_left, position=(0, 3, 12 - strip_h / 2 + 12), face="front", up="up")
    Place(bottom_back_right, position=(0, 3, 12 - strip_h / 2 + 12), face="front", up="up")
    Place(bottom_front_left, position=(0, 0, 12 - strip_h / 2 + 12), face="front", up="up")
    Place(bottom_front_right, position=(0, 0, 12 - strip_h / 2 + 12), face="front", up="up")

    assert (top_front_left.bar.bb.width + top_front_left.cap.radius - dt_depth) +
        (top_front_right.bar.bb.width + top_front_right.cap.radius) == 614 mm, "strips 614 long"
    assert top_front_left.bar.bb.height == 24 mm, "strips 24 tall"
    assert top_back_left.hanger.cord.c.diameter == 5 mm, "5 mm cord holes"
    assert top_back_left.hanger.cord.c.center.x - top_back_left.magnets.m[0].center.x ==
        -(200 mm - 55 mm), "ears 200 from the middle"
    assert len(top_front_left.magnets.m) + len(top_front_right.magnets.m) == 6, "six magnets a strip"
    assert top_front_right.magnets.m[0].center.x - top_front_left.magnets.m[0].center.x ==
        110 mm, "110 pitch across the middle"
    assert top_back_left.bb.width <= 600 mm, "a half fits the bed"
}
