# imported from slotted_plate.dxf by `aidl import --infer`: edit freely
# recognised: 21 of 21 pieces of outlines and holes in 6 shapes (4 Slot, 1 Rectangle, 1 Circle)
# patterns: 1 row
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
units mm
param width = 140 mm
param height = 50 mm
param slots_length = 20 mm
param slots_width = 6 mm
param slots_pitch = 25 mm
param slots_n = 3
param hole1_d = 5 mm
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # row: x from its end member
    for i in range(slots_n) {
        hole slots { h = Slot(center=(20 + i * slots_pitch, height / 2), length=slots_length, width=slots_width, rotation=90 deg) }
        Fixed(slots.h)
    }
    hole hole1 { h = Circle(center=(width - 12, height / 2), diameter=hole1_d) }
    Fixed(hole1.h)
}
