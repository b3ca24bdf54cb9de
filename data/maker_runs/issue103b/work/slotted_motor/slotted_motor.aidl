# imported from slotted_motor.dxf by `aidl import --infer`: edit freely
# recognised: 23 of 23 pieces of outlines and holes in 8 shapes (4 Slot, 3 Circle, 1 Rectangle)
# patterns: 1 grid, 1 mirrored pair
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 4 slots both about bore_c and at the corners: read as at the corners (their inset kept when the plate grows)
units mm
param width = 100 mm
param height = 70 mm
param slots_length = 8 mm
param slots_width = 3.4 mm
param slots_pitch = 31 mm
param slots_cols = 2
param slots_rows = 2
param holes_d = 5 mm
param holes_spacing = 50 mm
param bore_d = 22 mm
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    bore_c = (width - 35, height / 2)
    # grid: x about its middle, y about its middle, about bore_c
    for i in range(slots_cols) {
        for j in range(slots_rows) {
            hole slots { h = Slot(center=(bore_c.x + (i - (slots_cols - 1) / 2) * slots_pitch, bore_c.y + (j - (slots_rows - 1) / 2) * slots_pitch), length=slots_length, width=slots_width) }
            Fixed(slots.h)
        }
    }
    # mirrored about the centre line
    for s in [-1, 1] {
        hole holes { h = Circle(center=(10, height / 2 + s * holes_spacing / 2), diameter=holes_d) }
        Fixed(holes.h)
    }
    hole bore { h = Circle(center=bore_c, diameter=bore_d) }
    Fixed(bore.h)
}
