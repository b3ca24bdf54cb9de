# Request: a moon-phase wall hanging as a gift, cut from 3 mm birch ply in one piece. Seven
# moons 50 mm across in a row on a 62 mm pitch, joined by an 8 mm bar through their centres:
# waxing crescent, first quarter, waxing gibbous, full, waning gibbous, last quarter, waning
# crescent (phase angles 45, 90 ... 315 deg). The dark part of each moon is engraved filled
# (the terminator is a half ellipse, as the real moon's), the lit part left as bare wood;
# the full moon gets three engraved crater rings instead. Under the full moon a stem 8 mm wide
# drops 15 mm to a 170 x 26 mm plaque (R6 corners) engraved "TO THE MOON AND BACK" in bold
# letters 8 mm tall, filled. A 4 mm hanging hole 6 mm below the top of the first and last
# moon; the engraving keeps off the holes. All the cut's inside corners rounded R2.

thickness 3 mm

R = 25 mm
pitch = 62 mm
moons = 7

def phase(i) = 45 + i * 45                       # deg
def tk(th) = cos(min(th, 360 - th) * 1 deg)       # the terminator's x over the limb's
def side(th) = -1 if th > 180 else 1              # waning: dark on the right
def dark_pts(th) = ([(side(th) * R * cos(u * 1 deg), R * sin(u * 1 deg)) for u in range(90, 271, 5)] +
                    [(side(th) * tk(th) * R * cos(v * 1 deg), R * sin(v * 1 deg)) for v in range(-85, 90, 5)])

def moon(th=45, hang=false) -> solid {
    disc = Circle(center=(0, 0), radius=R)
    drawing shade {
        if th == 180 {
            c1 = Circle(center=(-8 mm, 7 mm), radius=5 mm)
            c2 = Circle(center=(9 mm, -4 mm), radius=3.5 mm)
            c3 = Circle(center=(-3 mm, -12 mm), radius=2.5 mm)
        } else {
            dark = Polygon(dark_pts(th), fill=true)
        }
        if hang {
            hole keep_off { c = Circle(center=(0, R - 6 mm), diameter=4 mm) }
        }
    }
}

solid hanging {
    for i in range(moons) {
        m = moon(th=phase(i), hang=(i == 0 or i == moons - 1))
        m.bb.center_x == (i - (moons - 1) / 2) * pitch
        m.bb.center_y == 0
    }
    bar = Rectangle(center=(0, 0), width=(moons - 1) * pitch, height=8 mm)
    stem = Rectangle(center=(0, -R - 7.5 mm + 2 mm), width=8 mm, height=15 mm + 4 mm)
    plaque = RoundedRectangle(center=(0, -R - 15 mm - 13 mm), width=170 mm, height=26 mm,
                              corner_radius=6 mm)
    drawing words {
        t = Text("TO THE MOON AND BACK", position=(0, -R - 15 mm - 13 mm), size=8 mm,
                 font="sans:Bold", valign="middle", fill=true, max_width=156 mm)
    }
    hole hang_l { c = Circle(center=(-(moons - 1) / 2 * pitch, R - 6 mm), diameter=4 mm) }
    hole hang_r { c = Circle(center=((moons - 1) / 2 * pitch, R - 6 mm), diameter=4 mm) }
    Fillet(2 mm)

    # the request's numbers
    assert len(m) == 7, "seven moons"
    assert m[1].bb.center_x - m[0].bb.center_x == 62 mm, "62 mm pitch"
    assert m[0].disc.diameter == 50 mm, "50 mm moons"
    assert phase(0) == 45 and phase(6) == 315 and phase(3) == 180, "45 .. 315, full in the middle"
    assert m[3].bb.bottom - plaque.bb.top == 15 mm, "stem drops 15 mm"
    assert plaque.bb.width == 170 mm and plaque.bb.height == 26 mm, "plaque 170 x 26"
    assert m[0].bb.top - hang_l.c.center.y == 6 mm, "hanging holes 6 mm down"
    assert words.t.bb.width <= plaque.bb.width - 10 mm, "words inside the plaque"
}
