# Request: a foam-dart shooting gallery for the kids, 6 mm plywood. A 400 x 80 plank stands
# 150 mm high on two trapezoid end plates (120 wide at the floor, 80 at the top, a 40 mm hole
# through the middle), set 10 mm in from the plank's ends and glued up through it with two 15 mm
# tabs each. Five knock-over targets stand on the plank 75 mm apart: each a 70 mm disc on a
# 20 mm stem, 140 mm tall overall, standing in a 60 x 20 foot, target and foot cross-halved
# 10 mm each with 0.15 mm clearance. Each disc has two engraved rings (60 and 40 mm) and its
# score engraved filled in bold 20 mm figures: 10, 20, 50, 20, 10 from left to right.

import "std/joints.aidl"

thickness 6 mm
T = 6 mm
PLANK_L = 400 mm
PLANK_D = 80 mm
HEIGHT = 150 mm
INSET = 10 mm
PITCH = 75 mm
DISC = 70 mm
TALL = 140 mm
SCORES = [10, 20, 50, 20, 10]

def target(score=10) -> solid {
    disc = Circle(center=(0, TALL - DISC / 2), diameter=DISC)
    stem = Rectangle(bottom_left=(-10, 0), width=20, height=TALL - DISC / 2)
    slot = cross_halving(depth=10 mm, thickness=T, clearance=0.15 mm, rotation=180 deg, cx=0, cy=0)
    drawing face {
        outer = Circle(center=(0, TALL - DISC / 2), diameter=60)
        inner = Circle(center=(0, TALL - DISC / 2), diameter=40)
        n = Text(str(score), position=(0, TALL - DISC / 2), size=20, font="sans:Bold",
                 valign="middle", fill=true)
    }
    Fixed(stem)
}

def foot() -> solid {
    bar = Rectangle(bottom_left=(-30, 0), width=60, height=20)
    slot = cross_halving(depth=10 mm, thickness=T, clearance=0.15 mm, cx=0, cy=20)
    Fixed(bar)
}

def end_plate() -> solid {
    body = Trapezoid(center=(0, HEIGHT / 2), bottom_width=120, top_width=PLANK_D, height=HEIGHT)
    strip = Rectangle(bottom_left=(-PLANK_D / 2, HEIGHT), width=PLANK_D, height=T)
    tabs = tab_and_slot(part="tab", length=PLANK_D, thickness=T, tabs=2, tab=15 mm, screw=0,
                        cx=0, cy=HEIGHT + T)
    hole window { c = Circle(center=(0, HEIGHT / 2), diameter=40) }
    Fixed(body)
}

assembly gallery {
    solid plank {
        board = Rectangle(center=(0, 0), width=PLANK_L, height=PLANK_D)
        left_slots = tab_and_slot(part="slot", length=PLANK_D, thickness=T, tabs=2, tab=15 mm,
                                  screw=0, rotation=90 deg, cx=-PLANK_L / 2 + INSET + T / 2, cy=0)
        right_slots = tab_and_slot(part="slot", length=PLANK_D, thickness=T, tabs=2, tab=15 mm,
                                   screw=0, rotation=90 deg, cx=PLANK_L / 2 - INSET - T / 2, cy=0)
        Fixed(board)
        assert board.bb.width == 400 mm and board.bb.height == 80 mm, "plank 400 x 80"
    }
    left_end = end_plate()
    right_end = end_plate()

    for i in range(5) {
        t = target(score=SCORES[i])
        f = foot()
        Place(t, rotation=(90 deg, 0, 0), position=((i - 2) * PITCH, T / 2, HEIGHT + T))
        Place(f, rotation=(90 deg, 0, 90 deg), position=((i - 2) * PITCH - T / 2, 0, HEIGHT + T))
    }

    assert len(t) == 5 and len(f) == 5, "five targets"
    assert t[0].disc.bb.top - t[0].stem.bb.bottom == 140 mm, "targets 140 tall"
    assert t[2].disc.diameter == 70 mm, "70 mm discs"
    assert left_end.body.height == 150 mm, "plank 150 up"
    assert t[2].face.n.text == "50", "bull in the middle"

    # sheet: plank on top, end plates and feet below, targets in a row
    Below(left_end, plank, gap=8)
    AlignLeft(left_end, plank)
    RightOf(right_end, left_end, gap=8)
    AlignTop(right_end, left_end)
    Below(t[0], left_end, gap=8)
    AlignLeft(t[0], plank)
    for i in range(4) {
        RightOf(t[i + 1], t[i], gap=6)
        AlignBottom(t[i + 1], t[i])
        RightOf(f[i + 1], f[i], gap=6)
        AlignBottom(f[i + 1], f[i])
    }
    RightOf(f[0], right_end, gap=8)
    AlignBottom(f[0], right_end)

    # 3D: plank flat on the end plates, targets standing on it facing -y
    Place(plank, position=(0, 0, HEIGHT))
    Place(left_end, rotation=(90 deg, 0, 90 deg), position=(-PLANK_L / 2 + INSET, 0, 0))
    Place(right_end, rotation=(90 deg, 0, 90 deg), position=(PLANK_L / 2 - INSET - T, 0, 0))
}
