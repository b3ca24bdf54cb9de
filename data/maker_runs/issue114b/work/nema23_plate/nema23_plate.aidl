# imported from nema23_plate.dxf by `aidl import --infer`: edit freely
# recognised: 11 of 11 pieces of outlines and holes in 8 shapes (7 Circle, 1 Rectangle)
# patterns: 1 mirrored pair, 1 grid
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# holes: layer `HOLES` in `OUTLINE`
# 2 holes mirrored about the centre line, nearer the top and bottom edges than it: each kept from its own edge (`holes_inset`), the far one too
# features by the far right edge are placed from it: a new width keeps their distance to that edge
units mm
param width = 150 mm
param height = 90 mm
param bore_x = 45 mm  # its centre, from the left edge
param holes_d = 6 mm
param holes_inset = 12 mm  # from the edges
param motor_holes_d = 5 mm
param motor_holes_pitch = 47.14 mm
param motor_holes_cols = 2
param motor_holes_rows = 2
param bore_d = 38.1 mm
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    bore_c = (bore_x, height / 2)
    # mirrored about the centre line
    for s in [-1, 1] {
        hole holes { h = Circle(center=(width - 12, height / 2 + s * (height / 2 - holes_inset)), diameter=holes_d) }
        Fixed(holes.h)
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
