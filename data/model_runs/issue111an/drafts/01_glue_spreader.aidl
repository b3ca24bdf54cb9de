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
            # FIX after the first valid program: W0115 (notch_pitch unread) and the row ran
            # off centre (-48..52 on a -50..50 blade: a half notch at the right corner)
            v = Polygon([(-50 + i * notch_pitch, -1), (-50 + (i + 0.5) * notch_pitch, 2),
                         (-50 + (i + 1) * notch_pitch, -1)], flexible=false)
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
