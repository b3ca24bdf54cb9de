# Request: a "football" output-jack plate for the flat rim of my solid-body guitar, cut
# from 3 mm black acrylic (flat: the rim is flat on this build).
# - Outline: a pointed oval (the lens two equal circles share), 70 mm long and 32 mm wide
#   before rounding, tips rounded R4.
# - A 9.6 mm hole in the middle for the 3/8-inch jack's thread.
# - Two 3.2 mm holes for #4 wood screws on the long axis, 52 mm apart, countersunk 6.5 mm.
# - A line engraved 2 mm inside the outline (a pinstripe), clear of the screw heads.

thickness 3 mm

length = 70 mm
width = 32 mm
# circles through both tips and the top/bottom of the lens: R - c = width / 2,
# R^2 - c^2 = (length / 2)^2
R = ((length / 2) ** 2 / (width / 2) + width / 2) / 2
c = R - width / 2

solid jack_plate {
    upper = Circle(center=(0, -c), radius=R)
    lower = Circle(center=(0, c), radius=R)
    lens = Intersect(upper, lower)
    Fillet(4)

    hole jack {
        j = Circle(center=(0, 0), diameter=9.6)
    }
    hole screws {
        a = Circle(center=(-26, 0), diameter=3.2)
        b = Circle(center=(26, 0), diameter=3.2)
    }
    Countersink(screws, diameter=6.5)

    drawing stripe {
        u = Circle(center=(0, -c), radius=R - 2, construction=true)
        l = Circle(center=(0, c), radius=R - 2, construction=true)
        s = Intersect(u, l)
    }

    assert abs(2 * sqrt(R ** 2 - c ** 2) - 70 mm) < 0.001 mm, "lens 70 long before rounding"
    assert abs(2 * (R - c) - 32 mm) < 0.001 mm, "lens 32 wide"
    assert abs(lens.bb.height - 32 mm) < 0.01 mm, "outline 32 wide"
    assert jack.j.diameter == 9.6 mm, "3/8 jack hole"
    assert screws.b.center.x - screws.a.center.x == 52 mm, "screws 52 apart"
    assert distance(stripe, screws) >= 3.25 mm - 1.6 mm, "pinstripe clear of the screw heads"
}
