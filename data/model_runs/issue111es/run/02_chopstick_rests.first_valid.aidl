# Request: "Two chopstick rests for our dinner table, cut from 4 mm bamboo ply. Each rest
# is two pieces slotted together crosswise so it stands on its own: a cradle 60 mm long and
# 20 mm tall, its two upper corners rounded R4, with a round dip of radius 8 mm, 5 mm deep,
# in the middle of its top edge for the chopsticks to lie in (the dip's edges softened R1.5);
# and a foot 40 mm long and 12 mm tall (upper corners R3) crossing it at the middle, both
# standing on the table. Cross-halving joint with 0.1 mm clearance. Kerf 0.15 mm."

import "std/joints.aidl"

units mm
t = 4 mm
thickness t
kerf 0.15 mm

cradle_len = 60 mm
cradle_h = 20 mm
dip_r = 8 mm
dip_depth = 5 mm
foot_len = 40 mm
foot_h = 12 mm
fit = 0.1 mm

def cradle_piece() -> solid {
    body = RoundedRectangle(bottom_left=(-cradle_len / 2, 0), width=cradle_len, height=cradle_h,
                            corner_radii=[4 mm, 4 mm, 0, 0])
    hole dip {
        c = Circle(center=(0, cradle_h + dip_r - dip_depth), radius=dip_r)
    }
    # slotted from below, half the foot's height: the two slots add up to the overlap
    h = cross_halving(depth=foot_h / 2, thickness=t, clearance=fit, rotation=180 deg, cx=0 mm, cy=0 mm)
    Fillet([body, dip.c], 1.5 mm)
}

def foot_piece() -> solid {
    body = RoundedRectangle(bottom_left=(-foot_len / 2, 0), width=foot_len, height=foot_h,
                            corner_radii=[3 mm, 3 mm, 0, 0])
    h = cross_halving(depth=foot_h / 2, thickness=t, clearance=fit, cx=0 mm, cy=foot_h)
}

assembly rests {
    for i in range(2) {
        cradle = cradle_piece()
        foot = foot_piece()
    }
    # on the sheet: each foot under its cradle, the second rest to the right
    Below(foot[0], cradle[0], gap=5 mm)
    AlignLeft(foot[0], cradle[0])
    RightOf(cradle[1], cradle[0], gap=5 mm)
    AlignTop(cradle[1], cradle[0])
    Below(foot[1], cradle[1], gap=5 mm)
    AlignLeft(foot[1], cradle[1])

    # in 3D: cradle along x, foot along y, crossing at the middle, both on the table
    for i in range(2) {
        Place(cradle[i], position=(i * 80 mm, t / 2, 0), face="front")
        Place(foot[i], position=(i * 80 mm - t / 2, 0, 0), face="right")
    }

    # the request's numbers
    assert len(cradle) == 2 and len(foot) == 2, "two rests of two pieces"
    assert cradle[0].body.bb.width == 60 mm and cradle[0].body.bb.height == 20 mm, "cradle 60 x 20"
    assert foot[0].body.bb.width == 40 mm and foot[0].body.bb.height == 12 mm, "foot 40 x 12"
    assert cradle[0].body.bb.top - cradle[0].dip.c.bottom.y == 5 mm, "dip 5 mm deep"
    assert cradle[0].h.depth + foot[0].h.depth == 12 mm, "slots add up to the foot's height"
    assert cradle[0].dip.c.bottom.y - cradle[0].h.cut.bb.top >= 5 mm, "wood left between dip and slot"
}
