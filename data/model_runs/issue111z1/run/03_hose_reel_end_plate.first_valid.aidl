# Garden: end plate (cut two) of a wall-hung garden-hose reel, 9 mm exterior ply.
# A 220 mm disc with a 25.4 mm (1 in) axle hole in the centre. Six lightening windows, each an
# annular sector from R40 to R90 and 40 deg wide, evenly spaced, the first centred at 30 deg;
# their corners R5. Four 4.5 mm screw holes for the hub flange on a 60 mm circle at 45, 135,
# 225 and 315 deg, countersunk 9 mm (flat-head wood screws). A 10 mm crank-handle hole at R100
# on the +x axis (between two windows). Engraved "HOSE" size 8 on the -y side at R65.
thickness 9 mm

param disc_d = 220 mm, min = 160, max = 300
param axle_d = 25.4 mm, min = 10, max = 40
param windows = 6, min = 3, max = 8

import "std/shapes.aidl"

solid reel_end {
    disc = Circle(center=(0, 0), diameter=disc_d)

    hole axle {
        a = Circle(center=(0, 0), diameter=axle_d)
    }
    hole window {
        w = Sector(center=(0, 0), radius=90, start_angle=10, end_angle=50, inner_radius=40)
    }
    lights = CircularPattern(window, windows, disc.center)

    hub = bolt_circle(count=4, pcd=60 mm, hole_d=4.5 mm, start=45 deg)
    Countersink(hub, diameter=9 mm)

    hole crank {
        c = Circle(center=(100, 0), diameter=10)
    }
    drawing label {
        word = Text("HOSE", (0, -65), size=8, valign="middle")
    }

    Fillet(5)

    assert disc.diameter == 220 mm, "220 mm disc"
    assert axle.a.diameter == 25.4 mm, "1 in axle"
    assert len(lights) == 6, "six windows"
    assert crank.c.center.x - disc.center.x == 100 mm, "crank hole at R100"
    assert crank.c.diameter == 10 mm, "10 mm crank hole"
}
