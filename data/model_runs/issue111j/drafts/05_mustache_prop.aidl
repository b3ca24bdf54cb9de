# Parties: a photo-booth mustache on a stick, 3 mm black acrylic, 148 mm across the curls.
# Each half: a lobe, an ellipse 76 x 28 mm (rx 38, ry 14) centred 32 mm out from the middle on
# y = 0, tilted 12 deg so its outer end rises; a curl at the outer end, a 16 mm disc centred
# 66 mm out and 10 mm up, with a 6 mm hole in it. The right half mirrors the left. A 20 mm knot
# disc in the middle, centred 2 mm up. A stick 10 mm wide, 160 mm long, straight down from the
# middle, its flat top 5 mm inside the knot, its bottom end with R5 corners (fully round).
units mm
thickness 3 mm

solid prop {
    axis = Line((0, -60), (0, 60), construction=true)
    Fixed(axis)

    solid left_half {
        lobe = Ellipse(center=(-32, 0), rx=38, ry=14, rotation=-12 deg)
        curl = Circle(center=(-66, 10), diameter=16)
        hole eye {
            c = Circle(center=(-66, 10), diameter=6)
        }
    }
    right_half = Mirrored(left_half, about=axis)

    knot = Circle(center=(0, 2), diameter=20)
    stick = RoundedRectangle(center=(0, -83), width=10, height=160, corner_radii=[0, 0, 5, 5])

    assert self.bb.width == 148 mm, "148 across the curls"
    assert left_half.lobe.rx == 38 mm and left_half.lobe.ry == 14 mm, "lobe 76 x 28"
    assert left_half.lobe.center.x == axis.start.x - 32 mm, "lobe 32 out"
    assert left_half.curl.diameter == 16 mm, "16 mm curl"
    assert left_half.curl.center.x == axis.start.x - 66 mm and left_half.curl.center.y == 10 mm, "curl 66 out, 10 up"
    assert left_half.eye.c.diameter == 6 mm, "6 mm hole in the curl"
    assert right_half.curl.center.x == axis.start.x + 66 mm, "right curl mirrored"
    assert knot.diameter == 20 mm and knot.center.y == 2 mm, "20 mm knot 2 up"
    assert stick.bb.width == 10 mm and stick.bb.height == 160 mm, "stick 10 x 160"
    assert stick.bb.top - knot.bb.bottom == 5 mm, "stick top 5 inside the knot"
    assert stick.center.x == knot.center.x, "stick straight down from the middle"
}
