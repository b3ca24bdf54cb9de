# Request (electronics): a tray to mount a 2.5" SSD in a 3.5" drive bay, 3 mm acrylic.
# A 101.6 x 146 plate (the 3.5" drive's footprint) with 3 mm round corners. Four 3.7 mm
# holes for the bay's 6-32 screws where a 3.5" drive has its bottom holes: 95.25 mm apart
# across, 41.3 and 85.7 mm from the front edge. The SSD lies flush with the back edge (its
# SATA connector where the 3.5" drive's is); its four M3 holes 61.72 mm apart across, 14 and
# 90.6 mm from the SSD's front (100 long), countersunk 6.3 mm for flat heads from the face
# the engraving is on (the underside in use). Under the SSD a honeycomb of 6 rows of 5 hex
# vents (8 mm across flats, 10 mm pitch), centred on the SSD. On the strip in front of the
# SSD, engraved: "2.5 TO 3.5 SSD TRAY" in 5 mm strokes and an arrow 10 long pointing back.

import "std/fasteners.aidl"

thickness 3 mm

W = 101.6 mm
L = 146 mm
ssd_len = 100 mm
ssd_front = L - ssd_len
pitch = 10 mm
row = pitch * sqrt(3) / 2

solid tray {
    plate = RoundedRectangle(bottom_left=(-W / 2, 0), width=W, height=L, corner_radius=3)
    Fixed(plate)

    hole bay {
        for y in [41.3 mm, 85.7 mm] {
            l = Circle(center=(-95.25 mm / 2, y), diameter=3.7)
            r = Circle(center=(95.25 mm / 2, y), diameter=3.7)
        }
    }

    s1 = clearance_hole(size=3, cx=-61.72 mm / 2, cy=ssd_front + 14)
    s2 = clearance_hole(size=3, cx=61.72 mm / 2, cy=ssd_front + 14)
    s3 = clearance_hole(size=3, cx=-61.72 mm / 2, cy=ssd_front + 90.6)
    s4 = clearance_hole(size=3, cx=61.72 mm / 2, cy=ssd_front + 90.6)
    Countersink([s1, s2, s3, s4], diameter=6.3)

    hole vent {
        h = RegularPolygon(center=(-2.25 * pitch, ssd_front + ssd_len / 2 - 2.5 * row),
                           across_flats=8, sides=6, rotation=30 deg)
    }
    vents = GridPattern(vent, 6, 5, pitch, row, stagger=true)

    drawing label {
        words = Text("2.5 TO 3.5 SSD TRAY", position=(0, 12), size=5)
        arrow = Polygon([(0, 38), (-4, 31), (-1.2, 31), (-1.2, 28), (1.2, 28), (1.2, 31), (4, 31)])
    }

    assert plate.bb.width == 101.6 mm and plate.bb.height == 146 mm, "3.5 in footprint"
    assert bay.r[0].center.x - bay.l[0].center.x == 95.25 mm, "bay holes 95.25 across"
    assert bay.l[0].center.y - plate.bb.bottom == 41.3 mm, "first bay hole 41.3 from the front"
    assert bay.l[1].center.y - plate.bb.bottom == 85.7 mm, "second bay hole 85.7 from the front"
    assert s2.c.center.x - s1.c.center.x == 61.72 mm, "SSD holes 61.72 across"
    assert s3.c.center.y - s1.c.center.y == 90.6 mm - 14 mm, "SSD holes 76.6 apart"
    assert plate.bb.top - s3.c.center.y == 100 mm - 90.6 mm, "SSD flush with the back"
    assert len(vents) == 30, "6 x 5 vents"
    assert label.arrow.bb.height == 10 mm, "arrow 10 long"
}
