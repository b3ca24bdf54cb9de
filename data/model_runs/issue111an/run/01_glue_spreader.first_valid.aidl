# Request (workshop): a notched glue spreader for veneer and laminate, 3 mm acrylic.
# Blade 100 mm wide x 60 mm tall; the bottom edge is serrated with 25 V notches
# 2 mm deep at a 4 mm pitch; the top corners rounded R8; a 6 mm hanging hole 10 mm
# below the top edge, centred; "GLUE 2 mm" engraved across the middle, 6 mm tall.
thickness 3 mm
kerf 0.15 mm

param notch_pitch = 4 mm, min = 3 mm, max = 6 mm
notches = 25

solid spreader {
    blade = RoundedRectangle(center=(0, 30), width=100, height=60,
                             corner_radii=[8, 8, 0, 0])
    hole teeth {
        for i in range(notches) {
            v = Polygon([(-48 + i * 4, -1), (-46 + i * 4, 2), (-44 + i * 4, -1)])
        }
    }
    hole hang {
        c = Circle(center=(0, 50), diameter=6)
    }
    drawing label {
        t = Text("GLUE 2 mm", position=(0, 30), size=6, valign="middle")
    }
    assert len(teeth.v) == 25, "25 notches"
    assert blade.bb.width == 100 mm and blade.bb.height == 60 mm, "blade 100 x 60"
    assert blade.bb.top - hang.c.center.y == 10 mm, "hang hole 10 below the top"
}
