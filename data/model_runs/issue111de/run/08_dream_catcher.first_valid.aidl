# Request: a dream catcher as a gift for a child's room (name ELLA), 3 mm birch ply.
# - A ring 150 mm across, 10 mm wide, with a hanging lug on top (R8, 5 mm hole, centre 80 mm
#   above the ring's centre).
# - Inside, a web of six nested hexagonal strands 2 mm wide: the outer hexagon's corners on the
#   ring, each next one's corners on the middles of the previous one's sides; six 2 mm spokes
#   from the innermost hexagon's corners to a 12 mm bead in the centre.
# - "SWEET DREAMS, ELLA" engraved along the top of the ring, 5 mm letters, standing on a circle
#   of R67.5 (inside the band).
# - Three 3 mm string holes in the ring's bottom at 250, 270 and 290 deg, on R70.
# - Three feathers 26 mm wide, 90, 110 and 90 mm long, pointed at the bottom, each with a 3 mm
#   hole 6 mm below its top, an engraved spine and five pairs of engraved barbs; they hang on
#   strings 40 mm below the holes.

thickness 3 mm

param name = "ELLA"

R0 = 65 mm          # the ring's inside radius
strand = 2 mm
levels = 6
holes_at = [250, 270, 290]
lengths = [90 mm, 110 mm, 90 mm]
drop = 40 mm

def feather(L=90 mm) -> solid {
    body = Spline([(0, L / 2), (9, L / 2 - 12), (13, L * 0.1), (9, -L / 2 + 20), (0, -L / 2),
                   (-9, -L / 2 + 20), (-13, L * 0.1), (-9, L / 2 - 12)], closed=true, corners=[4])
    hole eye { c = Circle(center=(0, L / 2 - 6), diameter=3) }
    drawing vanes {
        spine = Line((0, L / 2 - 11), (0, -L / 2 + 6))
        for i in range(5) {
            right_barb = Line((0, L / 2 - 20 - i * (L - 35 mm) / 5), (7, L / 2 - 26 - i * (L - 35 mm) / 5))
            left_barb = Line((0, L / 2 - 20 - i * (L - 35 mm) / 5), (-7, L / 2 - 26 - i * (L - 35 mm) / 5))
        }
    }
    Fixed(body)
}

assembly dream_catcher {
    solid catcher {
        ring = Shell(Circle(center=(0, 0), radius=R0), thickness=10)
        lug = Circle(center=(0, 80), radius=8)
        for k in range(levels) {
            hexagon = Shell(RegularPolygon(center=(0, 0), radius=R0 * cos(30 deg) ** k, sides=6,
                                           rotation=k * 30 deg), thickness=strand)
        }
        for j in range(6) {
            spoke = Stroke(Line((0, 0), polar((0, 0), R0 * cos(30 deg) ** (levels - 1),
                                               (levels - 1) * 30 deg + j * 60 deg)), width=strand)
        }
        bead = Circle(center=(0, 0), diameter=12)
        hole hang { c = Circle(center=(0, 80), diameter=5) }
        hole strings {
            for a in holes_at {
                s = Circle(center=polar((0, 0), 70, a * 1 deg), diameter=3)
            }
        }
        drawing words {
            base = Circle(center=(0, 0), radius=67.5, construction=true)
            w = Text("SWEET DREAMS, " + name, along=base, size=5)
        }
        Fixed(ring)
    }

    for i in range(3) {
        f = feather(L=lengths[i])
    }

    # on the sheet: the feathers in a row right of the ring
    RightOf(f[0], catcher, gap=6)
    AlignTop(f[0], catcher)
    RightOf(f[1], f[0], gap=6)
    AlignTop(f[1], f[0])
    RightOf(f[2], f[1], gap=6)
    AlignTop(f[2], f[1])

    # in 3D: hung on a wall hook, the ring's centre 300 mm up, the feathers 40 mm below their holes
    Place(catcher, position=(0, 0, 300), face="front", up="up")
    for i in range(3) {
        Place(f[i], face="front", up="up",
              position=(70 * cos(holes_at[i] * 1 deg), 0,
                        300 + 70 * sin(holes_at[i] * 1 deg) - drop - (lengths[i] / 2 - 6 mm)))
    }

    assert catcher.ring.bb.width == 150 mm, "150 mm ring"
    assert len(catcher.hexagon) == 6 and len(catcher.spoke) == 6, "six strands, six spokes"
    assert catcher.bead.diameter == 12 mm, "12 mm bead"
    assert len(catcher.strings.s) == 3, "three string holes"
    assert catcher.hang.c.center.y - catcher.ring.center.y == 80 mm, "lug 80 above"
    assert f[0].body.bb.height == 90 mm and f[1].body.bb.height == 110 mm, "feathers 90, 110, 90"
    assert abs(f[1].body.bb.width - 26 mm) < 0.5 mm, "26 wide"
    assert (f[0].body.bb.top - f[0].eye.c.center.y) == 6 mm, "hole 6 below the top"
    assert len(f[0].vanes.right_barb) == 5 and len(f[0].vanes.left_barb) == 5, "five pairs of barbs"
}
