# Request (science): a horizontal garden sundial for latitude 52 deg N, 6 mm ply (both
# parts). A round dial 220 mm across. Hour lines engraved from 6 am to 6 pm, each at the
# angle atan(sin(52) * tan(15 deg x hours from noon)) from the noon line, radiating from a
# point 50 mm south of the dial's centre and ending 90 mm from the centre; since the gnomon
# is 6 mm thick, the morning lines start 3 mm west and the afternoon lines 3 mm east of the
# noon line (noon: both, drawn north of the gnomon only). Hour numbers (8 mm) 100 mm from
# the centre on each line. "CARPE DIEM" (6 mm) and "52 N" (5 mm) engraved south of the
# lines; two 4.5 mm screw holes countersunk 9 mm at (+-45, -80) to fix it on a post.
# The gnomon: a right triangle whose style rises at 52 deg from the lines' origin (on the
# dial's surface) to an upright back edge 80 mm to the north; two 15 mm tabs (6 mm long)
# into mortises along the noon line, 0.1 mm clearance.

units mm
thickness 6 mm
kerf 0.15 mm

import "std/joints.aidl"

lat = 52 deg
ply = 6 mm
dial_d = 220 mm
oy = -50 mm            # the hour lines' origin, south of the centre
line_r = 90 mm
num_r = 100 mm
base = 80 mm
shoulder = ply / tan(lat)      # the style meets the tab line this far south of the origin
edge = base + shoulder         # the gnomon's tab edge, from its apex to its back

def hour_angle(h) = atan2(sin(lat) * sin(h * 15 deg), cos(h * 15 deg))
def side(h) = 0 mm if h == 0 else (ply / 2 if h > 0 else -ply / 2)
def pd(ox, th) = ox * sin(th) + oy * cos(th)
def reach(ox, th, r) = -pd(ox, th) + sqrt(pd(ox, th) ** 2 - ox ** 2 - oy ** 2 + r ** 2)

assembly sundial {
    solid dial {
        disc = Circle(center=(0, 0), diameter=dial_d)
        drawing hours {
            for i in range(13) {
                h = i - 6
                th = hour_angle(h)
                ox = side(h)
                t = reach(ox, th, line_r)
                if h != 0 {
                    ln = Line((ox, oy), (ox + t * sin(th), oy + t * cos(th)))
                }
                tn = reach(ox, th, num_r)
                num = Text(str(((h + 11) % 12) + 1), position=(ox + tn * sin(th),
                           oy + tn * cos(th)), size=8, valign="middle")
            }
            noon_w = Line((-ply / 2, oy + base), (-ply / 2, sqrt(line_r ** 2 - (ply / 2) ** 2)))
            noon_e = Line((ply / 2, oy + base), (ply / 2, sqrt(line_r ** 2 - (ply / 2) ** 2)))
            motto = Text("CARPE DIEM", position=(0, -68), size=6, valign="middle")
            lat_label = Text("52 N", position=(0, -98), size=5, valign="middle")
        }
        hole screws {
            a = Circle(center=(-45, -80), diameter=4.5)
            b = Circle(center=(45, -80), diameter=4.5)
        }
        Countersink(screws, diameter=9 mm)
        mortise = tab_and_slot(part="slot", length=edge, thickness=ply, tabs=2, tab=15 mm,
                               screw=0, clearance=0.1 mm, rotation=90 deg,
                               cx=0 mm, cy=oy - shoulder + edge / 2)
        assert hours.bb.left > disc.bb.left + 5 mm and hours.bb.right < disc.bb.right - 5 mm, "hours on the dial"
        assert hours.bb.top < disc.bb.top - 5 mm, "hours on the dial"
        assert hours.lat_label.bb.bottom > disc.bb.bottom + 5 mm, "label on the dial"
    }

    solid gnomon {
        shape = Polygon([(-shoulder, 0), (base, 0), (base, edge * tan(lat))])
        tabs = tab_and_slot(part="tab", length=edge, thickness=ply, tabs=2, tab=15 mm,
                            screw=0, clearance=0.1 mm, rotation=180 deg,
                            cx=(base - shoulder) / 2, cy=0 mm)
    }

    RightOf(gnomon, dial, gap=10)
    AlignBottom(gnomon, dial)

    assert len(dial.hours.num) == 13, "6 am to 6 pm: 13 numbers"
    assert abs(dial.disc.diameter - 220 mm) < 0.01, "dial 220"
    assert abs(hour_angle(3) - atan(sin(52 deg) * tan(45 deg))) < 0.001 deg, "3 pm angle"
    assert abs(hour_angle(-6) + 90 deg) < 0.001 deg, "6 am due west"
    assert abs(atan((gnomon.shape.points[2].y - gnomon.shape.points[1].y) / (gnomon.shape.points[1].x - gnomon.shape.points[0].x)) - 52 deg) < 0.01 deg, "style at 52 deg"
}
