# imported from far_edge_bracket.dxf by `aidl import --infer`: edit freely
# recognised: 11 of 11 pieces of outlines and holes in 5 shapes (3 Circle, 1 Rectangle, 1 Slot)
# patterns: 1 mirrored pair
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
units mm
param width = 100 mm
param height = 50 mm
param holes_d = 5.5 mm
param holes_spacing = 26 mm
param slot_length = 26 mm
param slot_width = 6 mm
param hole1_d = 8 mm
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # mirrored about the centre line
    for s in [-1, 1] {
        hole holes { h = Circle(center=(width - 12, height / 2 + s * holes_spacing / 2), diameter=holes_d) }
        Fixed(holes.h)
    }
    hole slot { h = Slot(center=(width - 40, height / 2), length=slot_length, width=slot_width) }
    Fixed(slot.h)
    hole hole1 { h = Circle(center=(15, height / 2), diameter=hole1_d) }
    Fixed(hole1.h)
}
