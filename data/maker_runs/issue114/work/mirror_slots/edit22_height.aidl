# imported from mirror_slots.dxf by `aidl import --infer`: edit freely
# recognised: 13 of 13 pieces of outlines and holes in 4 shapes (2 Slot, 1 Rectangle, 1 Circle)
# patterns: 1 mirrored pair
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 2 slots mirrored about the centre line, nearer the top and bottom edges than it: each kept from its own edge (`slots_inset`), the far one too
units mm
param width = 90 mm
param height = 150 mm
param slots_length = 30 mm
param slots_width = 8 mm
param slots_inset = 12 mm  # from the edges
param bore_d = 20 mm
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    bore_c = (width / 2, height / 2)
    # mirrored about the centre line
    for s in [-1, 1] {
        hole slots { h = Slot(center=(width / 2, height / 2 + s * (height / 2 - slots_inset)), length=slots_length, width=slots_width) }
        Fixed(slots.h)
    }
    hole bore { h = Circle(center=bore_c, diameter=bore_d) }
    Fixed(bore.h)
}
