# Request (sport): a display stand for a signed size-5 football (220 mm), from 6 mm ply:
# two 140 mm pieces that cross-halve at right angles. Each is 140 mm wide at the bottom;
# its top is a concave arc of the ball's own radius (110 mm), 25 mm above the bottom at
# the middle, so that the ball sits in both arcs. One piece is slotted halfway down from
# the top, the other halfway up from the bottom. "CHAMPIONS" engraved filled (bold 7 mm)
# on the left half of the first piece, "2026" on the right half of the second.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
param ball_d = 220 mm, min = 180 mm, max = 240 mm
param span = 140 mm, min = 100 mm, max = 180 mm
param waist = 25 mm, min = 16 mm, max = 40 mm    # height at the middle

def piece(from_top=true, word="", wx=0 mm) -> solid {
    body = Rectangle(bottom_left=(-span / 2, 0), width=span, height=ball_d / 2)
    hole cradle { ball = Circle(center=(0, waist + ball_d / 2), diameter=ball_d) }
    if from_top {
        halving = cross_halving(depth=waist / 2, thickness=t, cx=0 mm, cy=waist)
    } else {
        halving = cross_halving(depth=waist / 2, thickness=t, rotation=180 deg, cx=0 mm, cy=0 mm)
    }
    drawing mark {
        w = Text(word, position=(wx, 9), size=7, font="sans:Bold", valign="middle", fill=true)
    }
}

assembly stand {
    a = piece(from_top=true, word="CHAMPIONS", wx=-38 mm)
    b = piece(from_top=false, word="2026", wx=38 mm)

    Above(b, a, gap=8)
    AlignLeft(b, a)

    Place(a, position=(0, t / 2, 0), rotation=(90 deg, 0, 0))
    Place(b, position=(-t / 2, 0, 0), rotation=(90 deg, 0, 90 deg))

    assert a.body.bb.width == 140 mm, "140 mm wide"
    assert a.cradle.ball.radius == 110 mm, "the arc is the ball's radius"
    assert a.cradle.ball.bottom.y - a.body.bb.bottom == 25 mm, "25 mm at the middle"
    assert a.halving.depth + b.halving.depth == 25 mm, "the halvings meet"
    assert a.mark.w.size == 7 mm, "7 mm letters"
}
