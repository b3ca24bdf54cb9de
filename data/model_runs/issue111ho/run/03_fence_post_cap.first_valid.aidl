# Request (garden): a decorative cap for a 75 x 75 mm fence post, cut from 6 mm exterior
# ply. A 95 x 95 mm cap plate with its corners chamfered 8 mm and four 4 mm screw holes,
# countersunk for 8 mm heads, 22 mm in from each side (so they land well inside the
# post). On it stands a finial of two identical profiles slotted into each other as a
# cross (a cross halving, each slot half the piece's height): a 50 mm wide, 12 mm tall
# plinth, a 24 mm neck up to 40 mm, a 56 mm ball centred 66 mm up, and a point on top at
# 112 mm above the cap. Each profile has a 40 mm wide tab below that drops into a
# cross-shaped mortise in the cap plate.

units mm
thickness 6 mm

import "std/joints.aidl"

t = 6 mm
tip_y = 112 mm
half = (tip_y + t) / 2

def finial(mouth_y, turn) -> solid {
    plinth = Rectangle(center=(0, 6), width=50, height=12)
    neck = Rectangle(center=(0, 26), width=24, height=28)
    ball = Circle(center=(0, 66), diameter=56)
    spire = Hull(Circle(center=(0, 98), radius=6), Point(0, 112))
    tab = Rectangle(center=(0, -3), width=40, height=6)
    halving = cross_halving(depth=half, thickness=6 mm, rotation=turn, cx=0 mm, cy=mouth_y)
}

assembly post_cap {
    solid cap {
        body = Rectangle(center=(0, 0), width=95, height=95)
        Chamfer(body, 8)
        hole mortise {
            a = Rectangle(center=(0, 0), width=40, height=6)
            b = Rectangle(center=(0, 0), width=6, height=40)
        }
        hole screw {
            c = Circle(center=(-25.5, -25.5), diameter=4)
        }
        CornerPattern(screw, body, inset=22)
        Countersink(screw, diameter=8 mm)
    }
    upper = finial(mouth_y=tip_y, turn=0 deg)      # slotted down from the top
    lower = finial(mouth_y=-t, turn=180 deg)       # slotted up from the bottom

    RightOf(upper, cap, gap=10)
    AlignBottom(upper, cap)
    RightOf(lower, upper, gap=10)
    AlignBottom(lower, cap)

    Place(cap, position=(0, 0, 0))
    Place(upper, position=(0, 3, 6), face="front", up="up")
    Place(lower, position=(-3, 0, 6), face="right", up="up")

    assert cap.body.bb.width == 95 mm and cap.body.bb.height == 95 mm, "cap 95 x 95"
    assert cap.screw.c.center.x - cap.body.bb.left == 22 mm, "screws 22 mm in"
    assert 95 mm / 2 - 22 mm < 75 mm / 2 - 8 mm, "screws land 8 mm or more inside the post"
    assert upper.spire.bb.top == 112 mm, "point 112 mm above the cap"
    assert upper.ball.diameter == 56 mm and upper.ball.center.y == 66 mm, "56 mm ball at 66 mm"
    assert upper.plinth.bb.width == 50 mm and upper.plinth.bb.height == 12 mm, "plinth 50 x 12"
    assert upper.tab.bb.width == 40 mm, "40 mm tab"
    assert upper.halving.depth + lower.halving.depth == tip_y + t, "halvings meet"
}
