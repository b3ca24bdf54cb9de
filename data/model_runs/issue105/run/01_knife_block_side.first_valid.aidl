# Knife block side panel: 160 mm wide x 220 mm tall, 8 mm corner radius.
# Three crossbar slots 20 mm long x 3.2 mm wide, vertical, in a row 30 mm above the
# bottom edge, 45 mm apart, centered on the panel; a 40 mm round window centered
# 60 mm below the top edge.
thickness 3 mm

param w = 160 mm, min = 120 mm, max = 220 mm
param h = 220 mm, min = 160 mm, max = 300 mm

solid side {
    body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=8)

    hole slot0 {
        s = Slot(center=(-45, -80), length=20, width=3.2, rotation=90)
    }
    slots = LinearPattern(slot0, 3, (45, 0))
    # middle slot centered on the panel, 30 mm above the bottom edge (slot's bottom)
    AlignCenterX(slots[1], body)
    slot0.bb.bottom == body.bb.bottom + 30

    hole window {
        c = Circle(center=(0, 50), diameter=40)
    }
    AlignCenterX(window, body)
    At(window.c.center, body.center, dy=h / 2 - 60)
}
