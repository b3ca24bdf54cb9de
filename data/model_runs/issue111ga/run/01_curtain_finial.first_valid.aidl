# Request: a ball finial for the end of a 28 mm curtain pole, cut from 6 mm birch ply.
# Two profiles of the same outline (a flared base 32 mm wide, a 10 mm neck, a 44 mm ball,
# 72 mm tall from the cap to the top of the ball) slot into each other at right angles by a
# cross halving (0.1 mm clearance), and each has a 20 mm wide, 6 mm long tenon that goes into a
# cross mortise in a 44 mm round cap. Under the cap three 44 mm rings with a 28.4 mm bore are
# glued up into an 18 mm deep socket that pushes over the pole end. One finial (cut it twice
# for both ends of the pole).

import "std/joints.aidl"

t = 6 mm
thickness t

pole = 28 mm
fit = 0.4 mm
ball_d = 44 mm
height = 72 mm          # cap top to ball top
tenon_w = 20 mm
clear = 0.1 mm
rings = 3
cap_d = 44 mm

# half of the base-and-neck outline, from the axis at the bottom to the axis inside the ball
half = [(0, 0), (16, 0), (15, 4), (9, 10), (5.5, 20), (5, 30), (0, 30)]

def profile(from_top=false) -> solid {
    base = Spline(mirror(half, about="y"), closed=true, corners=[1, 11])
    ball = Circle(center=(0, height - ball_d / 2), diameter=ball_d)
    tenon = Rectangle(corner=(-tenon_w / 2, -t), opposite=(tenon_w / 2, 0))
    # the halving: each piece slotted through half of the 78 mm it spans (tenon included)
    if from_top {
        h = cross_halving(depth=(height + t) / 2, thickness=t, clearance=clear,
                          cx=0 mm, cy=height)
    } else {
        h = cross_halving(depth=(height + t) / 2, thickness=t, clearance=clear,
                          rotation=180 deg, cx=0 mm, cy=-t)
    }
}

def ring() -> solid {
    rim = Circle(center=(0, 0), diameter=cap_d)
    hole bore { c = Circle(center=(0, 0), diameter=pole + fit) }
}

assembly finial {
    a = profile(from_top=false)
    b = profile(from_top=true)

    solid cap {
        disc = Circle(center=(0, 0), diameter=cap_d)
        hole mortise {
            along_x = Rectangle(center=(0, 0), width=tenon_w + 2 * clear, height=t + 2 * clear)
            along_y = Rectangle(center=(0, 0), width=t + 2 * clear, height=tenon_w + 2 * clear)
        }
        AllowOverlap(mortise.along_x, mortise.along_y)
    }

    for i in range(rings) {
        r = ring()
    }

    # flat on the sheet: profiles side by side, the cap and rings in a row under them
    RightOf(b, a, gap=6)
    AlignBottom(b, a)
    Below(cap, a, gap=6)
    AlignLeft(cap, a)
    for i in range(rings) {
        Below(r[i], a, gap=6)
        RightOf(r[i], cap if i == 0 else r[i - 1], gap=6)
    }

    # assembled: rings stacked from z 0, the cap on them, the profiles standing in the cap
    for i in range(rings) {
        Place(r[i], position=(0, 0, i * t), face="up")
    }
    Place(cap, position=(0, 0, rings * t), face="up")
    Place(a, position=(0, t / 2, (rings + 1) * t), face="front", up="up")
    Place(b, position=(-t / 2, 0, (rings + 1) * t), face="right", up="up")

    # the request's numbers
    assert len(r) == 3, "three socket rings"
    assert rings * t == 18 mm, "an 18 mm deep socket"
    assert r[0].bore.c.diameter - 28 mm == 0.4 mm, "the bore fits a 28 mm pole"
    assert a.ball.diameter == 44 mm, "a 44 mm ball"
    assert a.ball.bb.top - a.base.bb.bottom == 72 mm, "72 mm from the cap to the top"
    assert a.base.points[1].x - a.base.points[11].x == 32 mm, "the base flares to 32 mm"
    assert a.tenon.bb.width == 20 mm and a.tenon.bb.height == 6 mm, "a 20 x 6 tenon"
    assert cap.disc.diameter == 44 mm, "a 44 mm cap"
    assert a.h.depth + b.h.depth == 72 mm + 6 mm, "the halvings meet"
}
