# Request: an adapter plate to mount a 2.5" SSD in a 3.5" drive tray, 3 mm black acrylic.
# The plate is the 3.5" drive's footprint, 101.6 x 147 mm. Four holes of 3.8 mm for the
# tray's 6-32 screws, 95.25 mm apart across (centred) and 76.2 mm apart lengthwise, the
# front pair 41.3 mm from the plate's front edge. The SSD (69.85 x 100 mm) lies centred
# across with its connector end flush with the plate's rear edge; its four M3 bottom holes
# are 61.72 mm apart across and 76.6 mm apart lengthwise, the rear pair 9.4 mm from the
# SSD's connector end: M3 clearance holes countersunk for 6 mm flat heads (the screws go
# in from under the plate). In front of the SSD a honeycomb of 3 rows x 7 hexagonal vents
# (8 mm across flats, 2 mm webs), and "SSD 1 TB" engraved (5 mm letters) between the vents
# and the SSD.

import "std/fasteners.aidl"

thickness 3 mm

solid adapter {
    # front edge at y = 0, rear edge at y = 147
    plate = Rectangle(bottom_left=(0, 0), width=101.6, height=147)

    hole bay {
        c = Circle(center=(0, 0), diameter=3.8)
    }
    bay_pat = Rectangle(center=(50.8, 41.3 + 76.2 / 2), width=95.25, height=76.2,
                        construction=true)
    CornerPattern(bay, bay_pat)

    ssd = clearance_hole(size=3)
    ssd_pat = Rectangle(center=(50.8, 147 - 9.4 - 76.6 / 2), width=61.72, height=76.6,
                        construction=true)
    CornerPattern(ssd, ssd_pat)
    Countersink(ssd, diameter=6 mm)

    # the SSD's outline, for checking only
    ssd_body = Rectangle(center=(50.8, 147 - 50), width=69.85, height=100, construction=true)

    hole vent {
        h = RegularPolygon(center=(50.8 - 32.5, 12), across_flats=8, sides=6,
                           rotation=30 deg)
    }
    vents = GridPattern(vent, 3, 7, (10, 10 * sqrt(3) / 2), stagger=true)

    drawing label {
        word = Text("SSD 1 TB", position=(50.8, 38), size=5)
    }

    # the request's numbers
    assert plate.bb.width == 101.6 mm and plate.bb.height == 147 mm, "3.5 in footprint"
    assert bay_pat.width == 95.25 mm and bay_pat.height == 76.2 mm, "tray screw pattern"
    assert bay.c.center.y - plate.bb.bottom == 41.3 mm, "front tray holes 41.3 from the front"
    assert ssd_pat.width == 61.72 mm and ssd_pat.height == 76.6 mm, "SSD screw pattern"
    assert plate.bb.top - ssd_pat.bb.top == 9.4 mm, "SSD rear holes 9.4 from the rear"
    assert ssd_body.bb.top == plate.bb.top, "SSD connector flush with the rear edge"
    assert len(vents) == 21, "3 x 7 vents"
    assert vents[6].h.center.x - vents[0].h.center.x == 60 mm, "8 mm flats + 2 mm webs"
    # FIX after the first valid program (no defect in the part): `vent.bb` was the original
    # vent only (row 0); the grid's top row is vents[14..20]
    assert vents[20].bb.top < label.bb.bottom and label.bb.top < ssd_body.bb.bottom,
        "label between the vents and the SSD"
}
