# Request (garden): a horizontal garden sundial for latitude 51.5 deg N, cut from 6 mm
# acrylic, two parts glued together:
# - dial: a 280 mm disc. The gnomon stands on the noon line, from the dial's centre 90 mm
#   northwards (up), in two 20 mm glued mortises. Hour lines engraved for 5 am to 7 pm from
#   the gnomon's foot: angle from the noon line atan2(sin(lat) * sin(H), cos(H)), H = 15 deg
#   per hour from noon; morning lines from the gnomon's west face (3 mm left of the noon
#   line), afternoon lines from its east face; each line runs from 95 to 115 mm out; the
#   noon line is engraved beside both faces. Hour numerals (5 .. 12 .. 7) engraved, sans,
#   9 mm high, centred 127 mm out on each line. "CARPE DIEM" engraved in serif, 12 mm high,
#   centred 35 mm south of the centre. Three 5 mm screw holes countersunk 10 mm on a 75 mm
#   radius at 200, 270 and 340 deg to fix it on a post.
# - gnomon: a right triangle 90 mm long whose sloping edge (the style) rises at the
#   latitude, 51.5 deg, from the dial's surface at the centre; two 20 mm tabs through the dial.

units mm
thickness 6 mm
import "std/joints.aidl"

lat = 51.5 deg
t = 6 mm
dial_d = 280 mm
g_len = 90 mm
r_in = 95 mm
r_out = 115 mm
r_num = 127 mm
def shade(h) = atan2(sin(lat) * sin(h * 15 deg), cos(h * 15 deg))
def dir(h) = 90 deg - shade(h)
def foot_x(h) = -t / 2 if h <= 0 else t / 2
def hour_name(h) = str((12 + h - 1) % 12 + 1)

assembly sundial {
    solid dial {
        disc = Circle(center=(0, 0), diameter=dial_d)
        mortise = tab_and_slot(part="slot", length=g_len, thickness=t, tabs=2, tab=20 mm, screw=0,
                               rotation=90 deg, cx=0 mm, cy=g_len / 2)
        hole screws {
            for k in range(3) {
                c = Circle(center=polar((0, 0), 75, [200 deg, 270 deg, 340 deg][k]), diameter=5)
            }
        }
        Countersink(screws, diameter=10 mm)

        drawing hours {
            for i in range(15) {
                ln = Line(polar((foot_x(i - 7), 0), r_in, dir(i - 7)),
                          polar((foot_x(i - 7), 0), r_out, dir(i - 7)))
                num = Text(hour_name(i - 7), position=polar((foot_x(i - 7), 0), r_num, dir(i - 7)),
                           size=9, font="sans", valign="middle")
            }
            noon_east = Line((t / 2, r_in), (t / 2, r_out))
        }
        drawing motto {
            words = Text("CARPE DIEM", position=(0, -35), size=12, font="serif", valign="middle")
        }
    }

    solid gnomon {
        blade = Polygon([(0, 0), (g_len, 0), (g_len, t + g_len * tan(lat)), (0, t)])
        tabs = tab_and_slot(part="tab", length=g_len, thickness=t, tabs=2, tab=20 mm, screw=0,
                            rotation=180 deg, cx=g_len / 2, cy=0 mm)
    }

    RightOf(gnomon, dial, gap=10)
    AlignBottom(gnomon, dial)

    # the request's numbers
    assert dial.disc.diameter == 280 mm, "dial 280 mm"
    assert len(dial.hours.ln) == 15, "5 am to 7 pm: 15 hour lines"
    assert len(dial.hours.num) == 15 and hour_name(-7) == "5" and hour_name(7) == "7", "numerals 5 .. 7"
    assert abs(dial.hours.ln[7].dx) < 1e-9, "noon line runs north"
    assert abs(dial.hours.ln[1].dy) < 1e-9 and dial.hours.ln[1].dx < 0, "6 am line due west"
    assert len(dial.screws.c) == 3, "three screw holes"
    assert distance(dial.screws.c[1].center, dial.disc.center) == 75 mm, "on a 75 mm radius"
    assert gnomon.blade.points[1].x - gnomon.blade.points[0].x == 90 mm, "gnomon 90 mm long"
    assert (abs(atan2(gnomon.blade.points[2].y - gnomon.blade.points[3].y,
                      gnomon.blade.points[2].x - gnomon.blade.points[3].x) - 51.5 deg) < 1e-9), "style at 51.5 deg"
    assert dial.disc.center.y - dial.motto.words.position.y == 35 mm, "motto 35 mm south"
}
