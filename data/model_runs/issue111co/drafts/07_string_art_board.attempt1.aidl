# Request: a string-art kit board for a craft afternoon: a 250 x 250 mm board with
# 12 mm rounded corners, 36 pilot holes of 1.5 mm for the panel pins round a heart
# 180 mm wide centred on the board (one hole at the heart's bottom tip, one in its top
# cleft), the heart's outline lightly engraved as a guide, "MIA & LEO" engraved in
# filled serif letters 12 mm tall under the heart, and two keyholes near the top
# corners to hang it on screws. 6 mm birch ply.

import "std/plates.aidl"

units mm
thickness 6 mm

param side = 250 mm, min = 180 mm, max = 380 mm
param heart_w = 180 mm, min = 100 mm, max = 220 mm
param nails = 36, min = 16, max = 72
param pin_d = 1.5 mm, min = 1 mm, max = 2.5 mm

k = heart_w / 32 mm        # the classic heart curve is 32 units wide
# the classic heart: x = 16 sin^3 t, y = 13 cos t - 5 cos 2t - 2 cos 3t - cos 4t
def hx(t) = k * 16 * sin(t) ** 3
def hy(t) = k * (13 * cos(t) - 5 * cos(2 * t) - 2 * cos(3 * t) - cos(4 * t))
pts = [(hx(i * 360 deg / nails), hy(i * 360 deg / nails)) for i in range(nails)]

solid board {
    plate = RoundedRectangle(center=(0, 0), width=side, height=side, corner_radius=12)

    hole pins {
        for p in pts {
            c = Circle(center=p, diameter=pin_d)
        }
    }
    drawing guide {
        line = Spline(pts, closed=true, corners=[0, nails // 2])
    }
    Rigid(pins, guide)
    CenterInside(pins, plate)

    drawing names {
        n = Text("MIA & LEO", position=(0, -side / 2 + 22), size=12, font="serif",
                 valign="middle", fill=true)
    }

    left_hook = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                        cx=-side / 2 + 25, cy=side / 2 - 30)
    right_hook = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                         cx=side / 2 - 25, cy=side / 2 - 30)

    # the request's numbers
    assert plate.bb.width == 250 mm and plate.bb.height == 250 mm, "250 x 250 board"
    assert len(pins.c) == 36 and pins.c[0].diameter == 1.5 mm, "36 pilot holes of 1.5 mm"
    assert abs(pins.bb.width - pin_d - 180 mm) < 0.5 mm, "heart 180 mm wide (hole centres)"
    assert abs(pins.bb.center_x - plate.bb.center_x) < 0.01 mm and
        abs(pins.bb.center_y - plate.bb.center_y) < 0.01 mm, "heart centred"
    assert names.n.size == 12 mm, "12 mm letters"
    assert names.bb.top < pins.bb.bottom - 5 mm, "names under the heart"
}
