# imported from vent_slots.dxf by `aidl import --infer`: edit freely
# recognised: 34 of 34 pieces of outlines and holes in 10 shapes (7 Slot, 2 Circle, 1 Rectangle)
# patterns: 1 row, 1 mirrored pair
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 2 holes mirrored about the centre line, nearer the side edges than it: each kept from its own edge (`holes_inset`), the far one too
units mm
param width = 180 mm
param height = 80 mm
param slots_length = 40 mm
param slots_width = 5 mm
param slots_pitch = 12 mm
param slots_n = 9
param holes_d = 4 mm
param holes_inset = 8 mm  # from the edges
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # row: x about its middle
    for i in range(slots_n) {
        hole slots { h = Slot(center=(width / 2 + (i - (slots_n - 1) / 2) * slots_pitch, height / 2), length=slots_length, width=slots_width, rotation=90 deg) }
        Fixed(slots.h)
    }
    # mirrored about the centre line
    for s in [-1, 1] {
        hole holes { h = Circle(center=(width / 2 + s * (width / 2 - holes_inset), height / 2), diameter=holes_d) }
        Fixed(holes.h)
    }
}
