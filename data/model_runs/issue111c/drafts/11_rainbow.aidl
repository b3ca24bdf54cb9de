# Rainbow shelf sitter: five nested half-rings (arcs) each 10 mm wide, the
# outer radius 100 mm, the inner opening 50 mm radius, touching so they make
# one part; a 200 x 10 mm base bar under them; each band's boundary engraved as
# an arc line; two 8 mm wide, 20 mm long slots in the bar's ends? no: the base
# has two 4 mm screw holes 15 mm in from its ends. Engraved "HELLO" 8 mm high
# in the opening, on the base.
thickness 3 mm

solid rainbow {
    for k in range(5) {
        band = Sector(center=(0, 0), radius=100 - 10 * k, inner_radius=90 - 10 * k,
                      start_angle=0, end_angle=180)
    }
    base = Rectangle(corner=(-100, -10), opposite=(100, 0))
    hole screw {
        c = Circle(center=(-85, -5), diameter=4)
    }
    other = Mirrored(screw, about=Line((0, -20), (0, 120), construction=true))
    drawing lines {
        for k in range(1, 5) {
            a = Arc(center=(0, 0), radius=100 - 10 * k, start_angle=0, end_angle=180)
        }
        word = Text("HELLO", position=(0, 2), size=8)
    }
}

assert rainbow.bb.width == 200 mm, "200 mm wide"
assert rainbow.bb.top - rainbow.base.bb.bottom == 110 mm, "100 mm radius on a 10 mm bar"
assert len(rainbow.band) == 5, "five bands"
assert rainbow.band[4].inner_radius == 50 mm, "50 mm opening"
assert rainbow.screw.c.center.x - rainbow.base.bb.left == 15 mm, "screw 15 mm in"
assert rainbow.base.bb.right - rainbow.other.c.center.x == 15 mm, "screw 15 mm in"
assert rainbow.lines.word.bb.width < 2 * 50 mm, "HELLO fits in the opening"
