# Bathroom corner shower shelf, 6 mm acrylic: a quarter disc of radius 200 mm (the corner of
# the walls at its centre), all corners rounded R3. Drain: three arc slots 6 mm wide on radii
# 80, 110 and 140 mm, each from 15 deg to 75 deg. Two 4 mm screw holes, each 10 mm in from one
# wall and 60 mm out along it from the corner, countersunk 8 mm.
thickness 6 mm
param r = 200 mm, min = 150 mm, max = 300 mm

solid shelf {
    body = Sector(center=(0, 0), radius=r, start_angle=0 deg, end_angle=90 deg)
    hole drain {
        for i in range(3) {
            a = ArcSlot(center=(0, 0), radius=80 mm + i * 30 mm, start_angle=15 deg, end_angle=75 deg, width=6)
        }
    }
    hole screws {
        s1 = Circle(center=(60, 10), diameter=4)
        s2 = Circle(center=(10, 60), diameter=4)
    }
    Countersink([screws.s1, screws.s2], diameter=8 mm)
    Fillet(3)

    assert body.radius == 200 mm, "radius 200"
    assert len(drain.a) == 3, "three drain slots"
    assert drain.a[2].radius == 140 mm and drain.a[0].radius == 80 mm, "slots on 80..140"
    assert drain.a[0].width == 6 mm, "slots 6 wide"
    assert screws.s1.center.y - body.bb.bottom == 10 mm, "screw 10 in from the wall"
}
