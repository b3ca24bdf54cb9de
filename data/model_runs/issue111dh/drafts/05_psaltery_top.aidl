# Request (music): the soundboard (top) of a bowed psaltery, 3 mm birch ply.
# An isosceles triangle 300 mm across the base and 480 mm high, the apex rounded R15 and the two
# base corners R10. Naturals G3 to E5 (13 strings) on the right, sharps G#3 A#3 C#4 D#4 F#4 G#4
# A#4 C#5 D#5 (9 strings) on the left. The naturals stand 4.5 mm, 13.5 mm, ... (9 mm pitch)
# right of the centre line, G3 innermost; each sharp mirrors the point halfway between its two
# naturals (G#3 at 9 mm left, A#3 at 18 mm left, C#4 at 36 mm left ...). Each string has a
# 5.5 mm tuning-pin hole 12 mm in from its slanted edge (measured square to it) and a 3 mm
# hitch-pin hole 15 mm above the base edge. Each tuning pin's note is engraved 3.5 mm tall,
# 9 mm below the pin. A rosette sound hole centred on the centre line 190 mm above the base:
# a 12 mm centre hole and eight 7 x 18 mm elliptic petals on a 17 mm radius, inside an
# engraved ring of R30.

units mm
thickness 3 mm

base_w = 300 mm
top_h = 480 mm
pitch = 9 mm
inset = 12 mm
hitch_y = 15 mm
naturals = ["G", "A", "B", "C", "D", "E", "F", "G", "A", "B", "C", "D", "E"]
# the natural below each sharp (its index in `naturals`)
sharp_k = [0, 1, 3, 4, 6, 7, 8, 10, 11]
sharps = ["G#", "A#", "C#", "D#", "F#", "G#", "A#", "C#", "D#"]
rose_y = 190 mm

# the height of the slanted edge at x, and how far below it a point 12 mm in (square) lies
def side_y(x) = top_h * (1 - abs(x) / (base_w / 2))
drop = inset * sqrt(1 + (top_h / (base_w / 2)) ** 2)
def nat_x(k) = 4.5 mm + pitch * k
def sharp_x(k) = -(nat_x(k) + pitch / 2)
# a point's distance from the line through a and b (for the asserts)
def off_line(p, a, b) = abs((b.x - a.x) * (a.y - p.y) - (a.x - p.x) * (b.y - a.y)) / distance(a, b)

solid psaltery_top {
    tri = Polygon([(-base_w / 2, 0), (base_w / 2, 0), (0, top_h)])
    Fillet(tri.points[2], 15)
    Fillet([tri.points[0], tri.points[1]], 10)

    for k in range(len(naturals)) {
        hole nat { c = Circle(center=(nat_x(k), side_y(nat_x(k)) - drop), diameter=5.5) }
        hole nat_hitch { c = Circle(center=(nat_x(k), hitch_y), diameter=3) }
    }
    for j in range(len(sharp_k)) {
        hole sharp { c = Circle(center=(sharp_x(sharp_k[j]), side_y(sharp_x(sharp_k[j])) - drop),
                                diameter=5.5) }
        hole sharp_hitch { c = Circle(center=(sharp_x(sharp_k[j]), hitch_y), diameter=3) }
    }

    drawing notes {
        for k in range(len(naturals)) {
            n = Text(naturals[k], position=(nat_x(k), side_y(nat_x(k)) - drop - 9), size=3.5,
                     valign="middle")
        }
        for j in range(len(sharp_k)) {
            s = Text(sharps[j], position=(sharp_x(sharp_k[j]),
                                          side_y(sharp_x(sharp_k[j])) - drop - 9),
                     size=3.5, valign="middle")
        }
        ring = Circle(center=(0, rose_y), radius=30)
    }

    hole rose_eye { c = Circle(center=(0, rose_y), diameter=12) }
    hole petal { e = Ellipse(center=(0, rose_y + 17), rx=3.5, ry=9) }
    petals = CircularPattern(petal, 8, (0, rose_y))

    # the request's numbers
    # FIX after the first valid program: W0405, this assert read the box before the Fillets;
    # the request's 300 x 480 is the sharp triangle whose corners are then rounded, so say so
    assert tri.points[1].x - tri.points[0].x == 300 mm and tri.points[2].y - tri.points[0].y == 480 mm,
        "300 base, 480 high (the sharp triangle)"
    assert len(nat) == 13 and len(sharp) == 9, "13 naturals, 9 sharps"
    assert nat[0].c.center.x == 4.5 mm and nat[1].c.center.x - nat[0].c.center.x == 9 mm,
        "naturals from 4.5 mm, 9 mm pitch"
    assert sharp[0].c.center.x == -9 mm and sharp[1].c.center.x == -18 mm and
        sharp[2].c.center.x == -36 mm, "G#3 9, A#3 18, C#4 36 left"
    assert off_line(nat[5].c.center, tri.points[1], tri.points[2]) == 12 mm, "tuning pins 12 in (right)"
    assert off_line(sharp[5].c.center, tri.points[2], tri.points[0]) == 12 mm, "tuning pins 12 in (left)"
    assert nat_hitch[0].c.center.y - tri.bb.bottom == 15 mm, "hitch pins 15 up"
    assert nat[4].c.center.y - notes.n[4].position.y == 9 mm, "notes 9 below the pins"
    assert rose_eye.c.center.y - tri.bb.bottom == 190 mm, "rosette 190 up"
    assert len(petals) == 8, "eight petals"
}
