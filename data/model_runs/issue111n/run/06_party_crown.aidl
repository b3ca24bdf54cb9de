# Parties: a birthday crown cut from 1.5 mm card. A band 540 x 50 mm; along its top
# edge ten triangular points, each 50 mm wide at the base and 40 mm tall, side by
# side, leaving 20 mm of plain band at each end. A five-point star 14 mm across (tips)
# cut out of each point, its centre 14 mm above the band's top edge. "HAPPY BIRTHDAY"
# cut through as a stencil in sans Bold, 20 mm high, centred in the band. The ends
# lock into a ring (20 mm overlap): a 25 mm slit down from the top edge 10 mm from
# the left end, and a 25 mm slit up from the bottom edge 10 mm from the right end.

units mm
thickness 1.5 mm

points = 10
base = 50 mm
tall = 40 mm

solid crown {
    band = Rectangle(center=(0, 0), width=540, height=50)

    for i in range(points) {
        p = Triangle(center=(-250 + base / 2 + i * base, 25 + tall / 2), base=base, height=tall)
    }

    hole star {
        s = Star(center=(-250 + base / 2, 25 + 14), points=5, outer_radius=7, inner_radius=3)
    }
    stars = LinearPattern(star, points, (base, 0))

    hole words {
        t = Text("HAPPY BIRTHDAY", (0, 0), size=20, font="sans:Bold", stencil=true, valign="middle")
    }
    CenterInside(words, band)

    cut slits {
        left = Line((-260, 25), (-260, 0))
        right = Line((260, -25), (260, 0))
    }

    # the request's numbers
    assert band.width == 540 mm and band.height == 50 mm, "band 540 x 50"
    assert len(p) == 10, "ten points"
    assert p[0].bb.width == 50 mm and p[0].bb.height == 40 mm, "points 50 wide, 40 tall"
    assert p[0].bb.left - band.bb.left == 20 mm, "20 mm plain at the left end"
    assert band.bb.right - p[9].bb.right == 20 mm, "20 mm plain at the right end"
    assert p[0].bb.bottom == band.bb.top, "points on the top edge"
    assert len(stars) == 10, "a star in each point"
    assert star.s.outer_radius == 7 mm, "stars 14 across"
    assert star.s.center.y - band.bb.top == 14 mm, "stars 14 above the band"
    assert star.s.center.x == p[0].c.x, "star under the tip"
    assert words.t.size == 20 mm, "20 mm letters"
    assert words.bb.width < 540 mm - 2 * 40 mm, "words clear of the slits"
    assert slits.left.length == 25 mm and slits.right.length == 25 mm, "25 mm slits"
    assert slits.left.start.x - band.bb.left == 10 mm, "left slit 10 from the end"
    assert band.bb.right - slits.right.start.x == 10 mm, "right slit 10 from the end"
}
