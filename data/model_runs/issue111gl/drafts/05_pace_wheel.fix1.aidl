# Request: a running pace wheel (a circular slide rule: pace x distance = time) for my club,
# three parts on one 5 mm pivot (a Chicago screw) through their centres. A 140 mm base disc
# of 3 mm ply carrying the outer log scale (one decade round the circle, increasing
# clockwise from 1 at the top): ticks from 45 mm radius outwards, 5 mm long at 1..9, 3 mm
# for tenths from 1 to 2, fifths from 2 to 5 and halves from 5 to 10, the 1..9 engraved
# just outside; "TIME MIN" over the top and "PACE X KM = TIME" under the bottom in the rim
# band. A 90 mm dial of 3 mm ply turning on it with the same scale engraved inwards from its
# edge (labels inside), a filled triangle marker at 1 ("PACE") and at the race distances
# 5 km ("5K"), 21.0975 km ("HM") and 42.195 km ("M"), and "DISTANCE KM" near the centre.
# A 16 mm wide clear acrylic cursor, 3 mm, from the pivot to 63 mm out with round ends and
# an engraved hairline along it.

units mm
thickness 3 mm

base_d = 140 mm
dial_d = 90 mm
pivot_d = 5 mm
r_edge = dial_d / 2

def theta(v) = 90 deg - 360 deg * log(v) / log(10)
def pt(r, a) = (r * cos(a), r * sin(a))

majors = [1, 2, 3, 4, 5, 6, 7, 8, 9]
minors = ([1 + 0.1 * i for i in range(1, 10)] + [2 + 0.2 * i for i in range(1, 15) if i % 5 != 0] +
          [5 + 0.5 * i for i in range(1, 10) if i % 2 != 0])
races = [5, 21.0975 / 10, 42.195 / 10]
race_names = ["5K", "HM", "M"]

# FIX after the first valid program: W0117 was true: `marker` was left over (the markers are
# written out where they are drawn, with fill=true), so it is deleted. No change to the part.

assembly pace_wheel {
    solid base {
        disc = Circle(center=(0, 0), diameter=base_d)
        hole pivot { c = Circle(center=(0, 0), diameter=pivot_d) }
        drawing scale {
            for v in majors {
                major = Line(pt(r_edge, theta(v)), pt(r_edge + 5 mm, theta(v)))
            }
            for v in minors {
                minor = Line(pt(r_edge, theta(v)), pt(r_edge + 3 mm, theta(v)))
            }
            ring = Circle(center=(0, 0), radius=r_edge + 6.5 mm, construction=true)
            for v in majors {
                num = Text(str(v), along=ring, angle=theta(v), size=3.5)
            }
            band = Circle(center=(0, 0), radius=62, construction=true)
            top_words = Text("TIME MIN", along=band, size=4)
            bottom_words = Text("PACE X KM = TIME", along=band, size=4, flip=true)
        }
    }

    solid dial {
        disc = Circle(center=(0, 0), diameter=dial_d)
        hole pivot { c = Circle(center=(0, 0), diameter=pivot_d) }
        drawing scale {
            for v in majors {
                major = Line(pt(r_edge, theta(v)), pt(r_edge - 5 mm, theta(v)))
            }
            for v in minors {
                minor = Line(pt(r_edge, theta(v)), pt(r_edge - 3 mm, theta(v)))
            }
            ring = Circle(center=(0, 0), radius=r_edge - 9.5 mm, construction=true)
            for v in majors {
                num = Text(str(v), along=ring, angle=theta(v), size=3.5)
            }
            index = Polygon([pt(33.5 mm, theta(1)), pt(30.5 mm, theta(1) + 3 deg), pt(30.5 mm, theta(1) - 3 deg)], fill=true)
            for v in races {
                race = Polygon([pt(33.5 mm, theta(v)), pt(30.5 mm, theta(v) + 3 deg), pt(30.5 mm, theta(v) - 3 deg)], fill=true)
            }
            inner = Circle(center=(0, 0), radius=25, construction=true)
            pace_word = Text("PACE", along=inner, angle=theta(1), size=3.5)
            for k in range(3) {
                race_word = Text(race_names[k], along=inner, angle=theta(races[k]), size=3.5)
            }
            middle = Circle(center=(0, 0), radius=14, construction=true)
            centre_words = Text("DISTANCE KM", along=middle, size=3, flip=true)
        }
    }

    solid cursor {
        arm = Slot(start=(0, 0), end=(0, 55), width=16)
        hole pivot { c = Circle(center=(0, 0), diameter=pivot_d) }
        drawing hairline { l = Line((0, 10), (0, 62)) }
    }

    # flat: side by side
    RightOf(dial, base, gap=10)
    AlignCenterY(dial, base)
    RightOf(cursor, dial, gap=10)
    AlignCenterY(cursor, dial)

    # assembled: stacked on the pivot
    Place(base, position=(0, 0, 0))
    Place(dial, position=(0, 0, 3))
    Place(cursor, position=(0, 0, 6))

    assert base.disc.diameter == 140 mm and dial.disc.diameter == 90 mm, "140 base, 90 dial"
    assert base.pivot.c.diameter == 5 mm and dial.pivot.c.diameter == 5 mm and cursor.pivot.c.diameter == 5 mm, "5 mm pivot"
    assert len(majors) == 9 and len(minors) == 9 + 12 + 5, "ticks: 9 majors; tenths, fifths, halves"
    assert abs(theta(10) - (theta(1) - 360 deg)) < 0.001 deg, "one decade round the circle"
    assert theta(2) < theta(1), "increasing clockwise"
    assert cursor.arm.bb.top == 63 mm, "the cursor reaches 63 mm"
    assert cursor.arm.width == 16 mm, "16 mm cursor"
    assert cursor.hairline.bb.top <= cursor.arm.bb.top, "hairline on the cursor"
    assert races[1] * 10 == 21.0975 and races[2] * 10 == 42.195, "half and full marathon"
}
