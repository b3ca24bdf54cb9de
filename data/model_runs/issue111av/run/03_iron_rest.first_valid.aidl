# Request: A soldering-iron rest for my electronics bench, cut from 4 mm plywood: three pieces
# that slot together with cross halvings (0.1 mm clearance), no glue. A spine 150 mm long and
# 25 mm tall stands on edge along the bench; two cradles cross it, each 70 mm wide: the front
# one 45 mm tall, 25 mm from the spine's front end, the back one 75 mm tall, 25 mm from the
# back end, so the iron lies sloping down to the front. Each cradle has a U seat at the top
# centre for the iron's handle: a round bottom of 12 mm radius, 18 mm deep from the top edge,
# flaring out to about 34 mm wide at the top edge. Round the cradles' top corners 3 mm.
# Engrave "HOT" 8 mm tall on the back cradle, under its seat. Show it assembled and flat.

units mm
thickness 4 mm

import "std/joints.aidl"

param ply = 4 mm, min = 3 mm, max = 6 mm
param fit = 0.1 mm, min = 0 mm, max = 0.3 mm

SPINE_L = 150 mm
SPINE_H = 25 mm
CRADLE_W = 70 mm
SEAT_R = 12 mm
SEAT_DEPTH = 18 mm
SEAT_TOP = 34 mm
CRADLE_AT = [25 mm, SPINE_L - 25 mm]   # cradle centres from the spine's front end

def cradle(height=45 mm, label="", ply=4 mm, fit=0.1 mm) -> solid {
    body = Rectangle(bottom_left=(-CRADLE_W / 2, 0), width=CRADLE_W, height=height)
    hole seat {
        bottom = Circle(center=(0, height - SEAT_DEPTH + SEAT_R), radius=SEAT_R, construction=true)
        u = Hull(bottom, Point(-SEAT_TOP / 2, height + 2), Point(SEAT_TOP / 2, height + 2))
    }
    # up from the bottom edge, half the spine's height
    halving = cross_halving(depth=SPINE_H / 2, thickness=ply, clearance=fit, rotation=180 deg,
                            cx=0, cy=0)
    if label != "" {
        drawing mark {
            t = Text(label, position=(0, SPINE_H + 6), size=8)
        }
    }
    Fillet([body.top_left, body.top_right], 3 mm)
}

assembly iron_rest {
    solid spine {
        body = Rectangle(bottom_left=(0, 0), width=SPINE_L, height=SPINE_H)
        for i in range(2) {
            # down from the top edge, half the spine's height
            halving = cross_halving(depth=SPINE_H / 2, thickness=ply, clearance=fit,
                                    cx=CRADLE_AT[i], cy=SPINE_H)
        }
    }
    front = cradle(height=45 mm, ply=ply, fit=fit)
    back = cradle(height=75 mm, label="HOT", ply=ply, fit=fit)

    # flat for cutting: the cradles side by side above the spine
    Above(front, spine, gap=8)
    AlignLeft(front, spine)
    RightOf(back, front, gap=8)
    AlignBottom(back, front)

    # assembled: the spine on edge along x, each cradle stood across it at its halving
    Place(spine, rotation=(90 deg, 0, 0), position=(0, ply / 2, 0))
    Place(front, rotation=(90 deg, 0, 90 deg), position=(CRADLE_AT[0] - ply / 2, 0, 0))
    Place(back, rotation=(90 deg, 0, 90 deg), position=(CRADLE_AT[1] - ply / 2, 0, 0))

    assert abs(spine.body.width - 150 mm) < 0.001 mm and abs(spine.body.height - 25 mm) < 0.001 mm,
        "spine 150 x 25"
    assert abs(front.body.height - 45 mm) < 0.001 mm and abs(back.body.height - 75 mm) < 0.001 mm,
        "cradles 45 and 75 tall"
    assert abs(front.body.width - 70 mm) < 0.001 mm, "cradles 70 wide"
    assert abs(spine.halving[0].cut.bb.center_x - spine.body.bb.left - 25 mm) < 0.001 mm,
        "front cradle 25 mm from the front end"
    assert abs(spine.body.bb.right - spine.halving[1].cut.bb.center_x - 25 mm) < 0.001 mm,
        "back cradle 25 mm from the back end"
    assert abs(back.body.bb.top - back.seat.bottom.bottom.y - 18 mm) < 0.001 mm, "seat 18 mm deep"
    assert abs(back.seat.bottom.radius - 12 mm) < 0.001 mm, "seat radius 12"
    assert front.seat.bottom.bottom.y - front.body.bb.bottom > 25 mm, "front seat clears the spine"
    assert back.mark.bb.top < back.seat.bottom.bottom.y - 2 mm and back.mark.bb.bottom > 25 mm,
        "HOT between the spine and the seat"
    assert abs(back.mark.t.size - 8 mm) < 0.001 mm, "HOT 8 mm tall"
}
