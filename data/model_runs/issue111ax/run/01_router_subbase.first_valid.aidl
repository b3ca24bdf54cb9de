# Request (workshop): a clear acrylic sub-base for my trim router, 6 mm acrylic. A 150 mm
# diameter disc with one straight edge cut 65 mm from the centre (a D shape) so the router
# can run along a fence. A 32 mm hole in the centre for the bit. Three M4 countersunk screw
# holes on a 100 mm pitch circle, at 90, 210 and 330 deg, countersunk for 8 mm heads.
# Engraved centring marks: four 10 mm ticks on the axes, from 20 to 30 mm out from the
# centre. Engraved near the straight edge, 5 mm tall: "BIT CL 65 mm" (the bit's centre line
# to the flat).
units mm
thickness 6 mm
import "std/shapes.aidl"

param dia = 150 mm, min = 120, max = 200
param flat = 65 mm, min = 50, max = 74
param bit_hole = 32 mm, min = 20, max = 50

solid subbase {
    disc = Circle(center=(0, 0), diameter=dia)
    keep = Rectangle(bottom_left=(-dia / 2 - 1, -flat), width=dia + 2, height=dia + 2)
    base = Intersect(disc, keep)

    hole bit {
        c = Circle(center=(0, 0), diameter=bit_hole)
    }

    screws = bolt_circle(count=3, pcd=100 mm, hole_d=4.5 mm, start=90 deg)
    Countersink(screws, diameter=8 mm)

    drawing marks {
        for a in [0, 90, 180, 270] {
            tick = Line((20 * cos(a * 1 deg), 20 * sin(a * 1 deg)),
                        (30 * cos(a * 1 deg), 30 * sin(a * 1 deg)))
        }
    }

    drawing label {
        t = Text("BIT CL 65 mm", position=(0, -flat + 9), size=5, valign="middle")
    }

    assert base.bb.width == 150 mm, "150 mm disc"
    assert bit.c.center.y - base.bb.bottom == 65 mm, "flat 65 mm from the centre"
    assert bit.c.diameter == 32 mm, "32 mm bit hole"
    assert len(screws.bolt) == 3, "three screws"
    assert screws.pitch.diameter == 100 mm, "100 mm pitch circle"
    assert label.bb.bottom > base.bb.bottom + 2 mm, "label clear of the flat"
    assert label.bb.top < screws.bolt[1].center.y - 4 mm, "label below the screws"
}
