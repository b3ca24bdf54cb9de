# Router circle-cutting jig (trammel): a 320 x 70 mm base with R10 corners; at
# the left a 52 mm hole for the router bit with four 5 mm router-base screw
# holes on a 64 mm circle around it (at 45 deg steps from 45 deg), the bit's
# center 35 mm from the left end; along the center line, 3 mm pivot-pin holes
# every 10 mm from 50 mm to 250 mm radius (21 holes), each numbered by its
# radius in cm every 50 mm ("5", "10", ... "25") engraved 4 mm high, 6 mm above.
thickness 6 mm

param step = 10 mm, min = 5 mm, max = 20 mm
count = 21

solid jig {
    base = RoundedRectangle(center=(125, 0), width=320, height=70, corner_radius=10)
    hole bit {
        c = Circle(center=(0, 0), diameter=52)
    }
    hole screw {
        c = Circle(center=(32 * cos(45 deg), 32 * sin(45 deg)), diameter=5)
    }
    screws = CircularPattern(screw, 4, bit.c.center)
    hole pin {
        p = Circle(center=(50, 0), diameter=3)
    }
    pins = LinearPattern(pin, count, (step, 0))
    drawing marks {
        for r in range(5, 30, 5) {
            t = Text(str(r), position=(r * 10 mm, 6), size=4)
        }
    }
    Fixed(bit)
    base.bb.left == bit.c.center.x - 35 mm
    AlignCenterY(base, bit)
}

assert jig.base.bb.width == 320 mm and jig.base.bb.height == 70 mm, "320 x 70"
assert jig.bit.c.diameter == 52 mm, "52 mm bit hole"
assert jig.bit.c.center.x - jig.base.bb.left == 35 mm, "bit 35 mm from the left end"
assert len(jig.pins) == 21, "21 pivot holes"
assert jig.pins[0].p.center.x - jig.bit.c.center.x == 50 mm, "first at 50 mm"
assert jig.pins[20].p.center.x - jig.bit.c.center.x == 250 mm, "last at 250 mm"
assert len(jig.screws) == 4, "four screw holes"
assert abs(distance(jig.screw.c.center, jig.bit.c.center) - 32 mm) < 0.001 mm, "64 mm screw circle"
assert jig.base.bb.right - jig.pins[20].p.center.x >= 5 mm, "room past the last pin"
