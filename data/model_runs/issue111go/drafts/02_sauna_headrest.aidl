# Request (bathroom): a sauna headrest in 9 mm birch ply. Two side profiles standing on
# the bench, each about 264 mm long, their top a concave arc of radius 300 mm that is
# 40 mm high at its lowest, about 45 mm at the front end and about 128 mm at the back end.
# Seven slats 25 mm wide across the headrest, 300 mm between the sides, following the
# curve with 8 mm gaps, each ending in 15 mm wide through-tenons (9 mm long, flush with
# the outside) in mortises whose top lies 5 mm under the curve; 0.2 mm play in the
# mortises. "LÖYLY" (the sauna's steam) engraved filled, 14 mm high, on the outside of the
# right side, near its high back end.

t = 9 mm
thickness t

R = 300 mm            # radius of the concave top
low = 40 mm           # height of the arc's lowest point
a0 = -100 deg         # front end of the arc
a1 = -45 deg          # back end of the arc
cx = -130 mm - R * cos(a0)   # the front end stands at x = -130
cy = low + R
cover = 5 mm          # side material above a mortise
slats = 7
slat_w = 25 mm
gap = 8 mm
inner = 300 mm        # between the sides
tenon_w = 15 mm
play = 0.2 mm

pitch = (slat_w + gap) / (R + cover) * 1 rad
mid = (a0 + a1) / 2
def ang(i) = mid + (i - (slats - 1) / 2) * pitch
rm = R + cover + t / 2          # radius of the mortises' (and slats') middles

def side(word="") -> solid {
    top = Arc(center=(cx, cy), radius=R, start_angle=a0, end_angle=a1)
    back = Line(top.end, (cx + R * cos(a1), 0))
    floor = Line((cx + R * cos(a1), 0), (cx + R * cos(a0), 0))
    front = Line((cx + R * cos(a0), 0), top.start)
    for i in range(slats) {
        hole mortise {
            m = Rectangle(center=(cx + rm * cos(ang(i)), cy + rm * sin(ang(i))),
                          width=tenon_w + play, height=t + play, rotation=ang(i) + 90 deg)
        }
    }
    if word != "" {
        drawing name {
            w = Text(word, position=(cx + R * cos(a1) - 45 mm, 30 mm), size=14,
                     font="sans:Bold", fill=true, valign="middle")
        }
    }
}

def slat() -> solid {
    body = Rectangle(center=(0, 0), width=inner, height=slat_w)
    l = Rectangle(center=(-inner / 2 - t / 2, 0), width=t, height=tenon_w)
    r = Rectangle(center=(inner / 2 + t / 2, 0), width=t, height=tenon_w)
}

assembly headrest {
    left = side()
    right = side(word="LÖYLY")
    RightOf(right, left, gap=6)
    AlignBottom(right, left)

    for i in range(slats) {
        s = slat()
        s.bb.center_x == 0
        s.bb.center_y == -30 mm - i * (slat_w + 6 mm)
        # each slat lies on the arc, its top face toward the arc's center
        Place(s, position=(0, cx + (rm + t / 2) * cos(ang(i)), cy + (rm + t / 2) * sin(ang(i))),
              face=(0, -cos(ang(i)), -sin(ang(i))), up=(0, -sin(ang(i)), cos(ang(i))))
    }

    # both sides face +x so that their profile's x runs to the back (+y)
    Place(left, position=(-inner / 2 - t, 0, 0), face="right", up="up")
    Place(right, position=(inner / 2, 0, 0), face="right", up="up")

    assert len(s) == 7, "seven slats"
    assert s[0].body.width == 300 mm and s[0].body.height == 25 mm
    assert s[0].bb.width == 300 mm + 2 * 9 mm, "tenons flush with the sides' outside"
    assert R == 300 mm and low == 40 mm
    assert abs(left.top.start.y - 45 mm) < 1 mm, "about 45 mm at the front"
    assert abs(left.top.end.y - 128 mm) < 1 mm, "about 128 mm at the back"
    assert abs(left.floor.length - 264 mm) < 1 mm, "about 264 mm long"
    assert abs((R + cover) * (pitch / 1 rad) - slat_w - 8 mm) < 0.01 mm, "8 mm gaps at the slats' faces"
    assert ang(0) - 2 deg > a0 and ang(slats - 1) + 2 deg < a1, "all slats on the arc"
}
