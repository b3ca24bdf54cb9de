# Request (music): a circle-of-fifths wheel for a music teacher, 3 mm ply, two discs on a
# 5 mm Chicago screw. Base disc 170 mm: the 12 major keys (C at the top, then G, D, A, E, B,
# F#, Db, Ab, Eb, Bb, F clockwise, 30 deg apart) engraved 7 mm high on a circle of radius
# 74 mm, their relative minors (Am, Em, ...) 4.5 mm high at radius 66 mm, engraved dividing
# lines between the keys from radius 63 to 84 mm, and each key's signature (0, 1#, ... 1b)
# 5 mm high at radius 50 mm, hidden by the top disc except in its window. Top disc 124 mm:
# a window from radius 44 to 57 mm spanning 30 deg at the top shows the signature of the key
# above it; a V notch 6 wide x 4 deep in the rim at the top points at that key; "I" engraved
# under the window, "IV" and "V" either side of it (IV counter-clockwise, V clockwise), and
# "CIRCLE OF FIFTHS" 5 mm high round the bottom, readable. 5 mm centre holes in both.

thickness 3 mm

majors = ["C", "G", "D", "A", "E", "B", "F#", "Db", "Ab", "Eb", "Bb", "F"]
minors = ["Am", "Em", "Bm", "F#m", "C#m", "G#m", "Ebm", "Bbm", "Fm", "Cm", "Gm", "Dm"]
sigs = ["0", "1#", "2#", "3#", "4#", "5#", "6#", "5b", "4b", "3b", "2b", "1b"]
def key_angle(i) = 90 deg - i * 30 deg

base_d = 170 mm
top_d = 124 mm
pivot_d = 5 mm

assert len(majors) == 12 and len(minors) == 12 and len(sigs) == 12, "12 keys"

assembly fifths_wheel {
    solid base {
        disc = Circle(center=(0, 0), diameter=base_d)
        hole pivot { c = Circle(center=(0, 0), diameter=pivot_d) }
        drawing keys {
            major_ring = Circle(center=(0, 0), radius=74, construction=true)
            minor_ring = Circle(center=(0, 0), radius=66, construction=true)
            sig_ring = Circle(center=(0, 0), radius=50, construction=true)
            for i in range(12) {
                major = Text(majors[i], along=major_ring, angle=key_angle(i), size=7)
                minor = Text(minors[i], along=minor_ring, angle=key_angle(i), size=4.5)
                sig = Text(sigs[i], along=sig_ring, angle=key_angle(i), size=5, valign="middle")
                divider = Line(polar((0, 0), 63, key_angle(i) + 15 deg),
                               polar((0, 0), 84, key_angle(i) + 15 deg))
            }
        }
        assert len(keys.major) == 12, "12 major keys"
    }

    solid top {
        disc = Circle(center=(0, 0), diameter=top_d)
        hole pivot { c = Circle(center=(0, 0), diameter=pivot_d) }
        hole window {
            w = Sector(center=(0, 0), radius=57, start_angle=75 deg, end_angle=105 deg,
                       inner_radius=44)
        }
        hole pointer {
            v = Polygon([(-3, top_d / 2 + 1), (3, top_d / 2 + 1), (0, top_d / 2 - 4)], overrun=true)
        }
        drawing labels {
            inner = Circle(center=(0, 0), radius=36, construction=true)
            mid = Circle(center=(0, 0), radius=50, construction=true)
            title_ring = Circle(center=(0, 0), radius=52, construction=true)
            one = Text("I", along=inner, angle=90 deg, size=6, valign="middle")
            four = Text("IV", along=mid, angle=120 deg, size=6, valign="middle")
            five = Text("V", along=mid, angle=60 deg, size=6, valign="middle")
            title = Text("CIRCLE OF FIFTHS", along=title_ring, flip=true, size=5)
        }
        assert window.w.radius - window.w.inner_radius == 13 mm, "window 44 to 57"
    }
    RightOf(top, base, gap=10)
    AlignCenterY(top, base)
    assert base.disc.diameter == 170 mm and top.disc.diameter == 124 mm, "disc sizes"
    # the signature ring is covered by the top disc, the key names are not
    assert base.keys.sig_ring.radius < top_d / 2 and base.keys.minor_ring.radius - 4.5 mm / 2 > top_d / 2,
        "signatures hidden, minors visible"
}
