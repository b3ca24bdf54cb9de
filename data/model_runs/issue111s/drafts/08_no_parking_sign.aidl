# Sign: a cut-out "no parking" sign in 5 mm acrylic, all one piece. A ring 200 mm across and
# 20 mm wide (160 mm inside); a letter "P" in sans Bold, 110 mm tall, centred; a diagonal bar
# 20 mm wide from the ring's top-left to its bottom-right (at -45 degrees), running through
# the P and into the ring so everything is joined. Two 6 mm screw holes in the ring, at the
# top and bottom, on a 180 mm circle.

thickness 5 mm
param od = 200 mm, min = 150 mm, max = 300 mm
param band = 20 mm, min = 15 mm, max = 30 mm

solid sign {
    # the ring in a solid of its own: its opening must not cut the letter and the bar
    solid ring {
        disc = Circle(center=(0, 0), diameter=od)
        hole inside {
            c = Circle(center=(0, 0), diameter=od - 2 * band)
        }
    }
    solid letter {
        p = Text("P", (0, 0), size=110, font="sans:Bold", valign="middle")
    }
    solid bar {
        b = Rectangle(center=(0, 0), width=od - band, height=band, rotation=-45 deg)
    }
    CenterInside(letter, ring.disc)
    At(bar.b.center, ring.disc.center)

    hole screw {
        c = Circle(center=(0, 90), diameter=6)
    }
    other_screw = Mirrored(screw, Line((-100, 0), (100, 0), construction=true))
    Coincident(screw.c.center, polar(ring.disc.center, 90, 90 deg))

    assert ring.disc.diameter == 200 mm, "200 across"
    assert ring.inside.c.diameter == 160 mm, "160 inside: a 20 mm ring"
    assert bar.b.height == 20 mm, "bar 20 wide"
    assert abs(letter.bb.height - 110 mm) < 2 mm, "P about 110 tall"
    assert distance(screw.c.center, other_screw.c.center) == 180 mm, "screws on a 180 mm circle"
    assert screw.c.diameter == 6 mm, "6 mm screws"
}
