# Wall trellis panel (garden): 200 x 300 mm, R8 corners, 6 mm plywood; a lattice of diamond
# openings (squares of 20 mm side turned 45 deg) on a diagonal grid that leaves 6 mm strips
# between neighbours, centered on the panel, only whole diamonds, none closer than 15 mm to the
# panel's edge; four 4.5 mm screw holes 10 mm in from each corner, countersunk 9 mm.

thickness 6 mm

param side = 20 mm, min = 14 mm, max = 26 mm
param strip = 6 mm, min = 4 mm, max = 10 mm
border = 15 mm
W = 200 mm
H = 300 mm
d = side + strip                # pitch along the diagonals
p = d * sqrt(2)                 # pitch of the lattice along x and y
half = side / sqrt(2)           # center to tip of a diamond

solid trellis {
    body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=8)
    Fixed(body)

    hole lattice {
        # one flat loop over the 13 x 21 lattice sites (i = k // 21 - 6, j = k % 21 - 10)
        for k in range(13 * 21) {
            if abs((k // 21 - 6) * p / 2) + half <= W / 2 - border and abs((k % 21 - 10) * p / 2) + half <= H / 2 - border and (k // 21 + k % 21) % 2 == 0 {
                dia = RegularPolygon(center=((k // 21 - 6) * p / 2, (k % 21 - 10) * p / 2), radius=half, sides=4)
            }
        }
    }

    hole screw {
        c = Circle(center=(-90, -140), diameter=4.5)
    }
    screws = CornerPattern(screw, body, inset=10)
    Countersink(screws, diameter=9)

    assert body.bb.width == 200 mm, "200 mm wide"
    assert body.bb.height == 300 mm, "300 mm tall"
    assert lattice.bb.left - body.bb.left >= 15 mm, "15 mm border left"
    assert body.bb.top - lattice.bb.top >= 15 mm, "15 mm border top"
    assert abs(lattice.bb.center_x - body.bb.center_x) < 0.01 mm, "lattice centered in x"
    assert abs(lattice.bb.center_y - body.bb.center_y) < 0.01 mm, "lattice centered in y"
    assert lattice.dia[0].bb.width == 20 mm * sqrt(2), "20 mm squares turned 45 deg"
    assert len(lattice.dia) >= 40, "a full lattice"
    assert screws[0].c.center.x - body.bb.left == 10 mm, "screws 10 mm in"
    assert len(screws) == 4, "four screws"
}
