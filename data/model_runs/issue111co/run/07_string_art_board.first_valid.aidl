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

# the heart of two circles and a point (the prompt's: circles r 9 at (+-8, 5), tip
# (0, -16), 34 units wide), scaled; its outline is a tangent line and an arc each side,
# so the pins can be spaced evenly along it by arc length s (0 at the bottom tip,
# counter-clockwise: up the right side, over the right lobe to the cleft, then the left)
k = heart_w / 34 mm
R = 9 * k
cx0 = 8 * k
cy0 = 5 * k
tip_y = -16 * k
dc = sqrt(cx0 ** 2 + (cy0 - tip_y) ** 2)
Lt = sqrt(dc ** 2 - R ** 2)                           # tangent line, tip to lobe
dir_a = atan2(cy0 - tip_y, cx0) - asin(R / dc)        # its direction
a0 = dir_a - 90 deg                                   # where it meets the lobe, about its centre
a1 = atan2(sqrt(R ** 2 - cx0 ** 2), -cx0)             # the cleft, about the right centre
half = Lt + R * (a1 - a0) / 1 rad
total = 2 * half
def rx(s) = s * cos(dir_a) if s <= Lt else cx0 + R * cos(a0 + (s - Lt) / R * 1 rad)
def ry(s) = tip_y + s * sin(dir_a) if s <= Lt else cy0 + R * sin(a0 + (s - Lt) / R * 1 rad)
def nx(s) = rx(s) if s <= half else -rx(total - s)
def ny(s) = ry(s) if s <= half else ry(total - s)
pts = [(nx(i * total / nails), ny(i * total / nails)) for i in range(nails)]

solid board {
    plate = RoundedRectangle(center=(0, 0), width=side, height=side, corner_radius=12)

    hole pins {
        for p in pts {
            c = Circle(center=p, diameter=pin_d)
        }
    }
    # the guide: the heart's own outline (the pins sit on it, so it crosses them)
    drawing guide {
        tip = Point(0, tip_y)
        t_r = Point(rx(Lt), ry(Lt))
        t_l = Point(-rx(Lt), ry(Lt))
        cleft = Point(0, ry(half))
        l_r = Line(tip, t_r)
        arc_r = Arc(center=(cx0, cy0), start=t_r, end=cleft)
        arc_l = Arc(center=(-cx0, cy0), start=cleft, end=t_l)
        l_l = Line(t_l, tip)
        AllowOverlap(guide, self)
    }
    Rigid(pins, guide)
    CenterInside(guide, plate)

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
    assert abs(guide.bb.width - 180 mm) < 0.01 mm, "heart 180 mm wide"
    assert abs(guide.bb.center_x - plate.bb.center_x) < 0.01 mm and
        abs(guide.bb.center_y - plate.bb.center_y) < 0.01 mm, "heart centred"
    assert abs(distance(pins.c[1].center, pins.c[0].center) - distance(pins.c[20].center, pins.c[19].center)) < 0.5 mm,
        "pins evenly spaced"
    assert names.n.size == 12 mm, "12 mm letters"
    assert names.bb.top < pins.bb.bottom - 5 mm, "names under the heart"
}
