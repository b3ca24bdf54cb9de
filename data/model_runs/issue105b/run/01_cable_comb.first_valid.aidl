# Desk cable comb: a plate 120 mm wide x 30 mm tall, 3 mm acrylic, with 5 cable
# slots 6 mm wide and 18 mm deep open at the top edge (round bottoms), spaced
# 20 mm apart and centered, and 2 screw holes of 4 mm diameter 8 mm above the
# bottom edge, 10 mm in from each side.

units mm
thickness 3 mm

param slots = 5, min = 2, max = 5
param pitch = 20 mm, min = 12 mm, max = 24 mm
param slot_w = 6 mm, min = 3 mm, max = 10 mm
param slot_depth = 18 mm, min = 8 mm, max = 20 mm

solid comb {
    body = RoundedRectangle(center=(0, 0), width=120, height=30, corner_radius=3)

    hole slot {
        s = Rectangle(center=(0, 0), width=slot_w, height=slot_depth + 2)
        tip = Circle(center=(0, 0), diameter=slot_w)
    }
    # the round bottom sits at the bottom of the rectangle
    Coincident(slot.tip.center, slot.s.bottom.midpoint)
    row = LinearPattern(slot, slots, (pitch, 0))

    # slot bottoms at slot_depth below the top edge, open past the top edge
    slot.tip.center.y == body.bb.top - slot_depth + slot_w / 2
    # the row is centered on the plate
    (row[0].s.center.x + row[slots - 1].s.center.x) / 2 == body.center.x

    hole screw {
        c = Circle(center=(-50, -7), diameter=4)
    }
    At(screw.c.center, body.bottom_left, dx=10, dy=8)
    other = Mirrored(screw, about=Line(body.top.midpoint, body.bottom.midpoint, construction=true))
}
