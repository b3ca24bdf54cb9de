# Fidget spinner body for 608 bearings (22 mm): a 36 mm center disc with a 22 mm bearing
# hole; three 32 mm lobes whose centers sit 33 mm from the center, 120 degrees apart
# (first one straight up), each with a 22 mm hole for a weight bearing; the lobes join the
# center with 24 mm wide arms; every concave corner rounded 4 mm.

param reach = 33 mm, min = 30 mm, max = 40 mm

solid spinner {
    hub = Circle(center=(0, 0), diameter=36)
    solid lobe {
        ring = Circle(center=(0, 33), diameter=32)
        arm = Rectangle(center=(0, 16.5), width=24, height=33)
        hole bore {
            c = Circle(center=(0, 33), diameter=22)
        }
        Concentric(bore.c, ring)
    }
    Coincident(lobe.ring.center, polar(hub.center, reach, 90 deg))
    AlignCenterX(lobe.arm, hub)
    lobe.arm.bottom.midpoint.y == hub.center.y
    lobes = CircularPattern(lobe, 3, hub.center)
    hole center_bore {
        c = Circle(center=(0, 0), diameter=22)
    }
    Concentric(center_bore.c, hub)
    Fillet(4)
    assert len(lobes) == 3, "three lobes"
    assert distance(lobe.ring.center, hub.center) == 33 mm, "lobes 33 mm out"
    assert center_bore.c.diameter == 22 mm and lobe.bore.c.diameter == 22 mm, "608 bearing holes"
}
