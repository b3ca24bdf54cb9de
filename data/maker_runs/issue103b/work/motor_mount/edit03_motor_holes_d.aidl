# imported from motor_mount.dxf by `aidl import --infer`: edit freely
# recognised: 17 of 17 pieces of outlines and holes in 8 shapes (5 Circle, 2 Slot, 1 Rectangle)
# patterns: 1 mirrored pair, 1 grid
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# holes: layer `HOLES` in `OUTLINE`
units mm
param width = 80 mm
param height = 60 mm
param slots_length = 16 mm
param slots_width = 5.5 mm
param slots_spacing = 36 mm
param motor_holes_d = 3.0 mm
param motor_holes_pitch = 31 mm
param motor_holes_cols = 2
param motor_holes_rows = 2
param bore_d = 22 mm
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    bore_c = (width - 30, height / 2)
    # mirrored about the centre line
    for s in [-1, 1] {
        hole slots { h = Slot(center=(10, height / 2 + s * slots_spacing / 2), length=slots_length, width=slots_width, rotation=90 deg) }
        Fixed(slots.h)
    }
    # grid: x about its middle, y about its middle, about bore_c
    for i in range(motor_holes_cols) {
        for j in range(motor_holes_rows) {
            hole motor_holes { h = Circle(center=(bore_c.x + (i - (motor_holes_cols - 1) / 2) * motor_holes_pitch, bore_c.y + (j - (motor_holes_rows - 1) / 2) * motor_holes_pitch), diameter=motor_holes_d) }
            Fixed(motor_holes.h)
        }
    }
    hole bore { h = Circle(center=bore_c, diameter=bore_d) }
    Fixed(bore.h)
}
