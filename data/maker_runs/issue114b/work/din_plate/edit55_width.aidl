# imported from din_plate.dxf by `aidl import --infer`: edit freely
# recognised: 17 of 17 pieces of outlines and holes in 8 shapes (5 Circle, 2 Slot, 1 Rectangle)
# patterns: 1 mirrored pair, 1 row
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 2 slots mirrored about the centre line, nearer the side edges than it: each kept from its own edge (`slots_inset`), the far one too
units mm
param width = 180 mm
param height = 60 mm
param slots_length = 16 mm
param slots_width = 5.5 mm
param slots_inset = 12 mm  # from the edges
param holes_d = 4 mm
param holes_pitch = 25 mm
param holes_n = 5
param holes_y = 20 mm  # its line, from the bottom edge
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # mirrored about the centre line
    for s in [-1, 1] {
        hole slots { h = Slot(center=(width / 2 + s * (width / 2 - slots_inset), height / 2), length=slots_length, width=slots_width) }
        Fixed(slots.h)
    }
    # row: x about its middle
    for i in range(holes_n) {
        hole holes { h = Circle(center=(width / 2 + (i - (holes_n - 1) / 2) * holes_pitch, holes_y), diameter=holes_d) }
        Fixed(holes.h)
    }
}
