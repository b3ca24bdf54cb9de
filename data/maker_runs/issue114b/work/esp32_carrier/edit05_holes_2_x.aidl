# imported from esp32_carrier.dxf by `aidl import --infer`: edit freely
# recognised: 14 of 14 pieces of outlines and holes in 7 shapes (6 Circle, 1 RoundedRectangle)
# patterns: 1 mirrored pair, 1 grid
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 2 holes mirrored about the centre line, nearer the top and bottom edges than it: each kept from its own edge (`holes_inset`), the far one too
# features by the far right edge are placed from it: a new width keeps their distance to that edge
units mm
param width = 120 mm
param height = 70 mm
param corner_radius = 5 mm
param holes_d = 5 mm
param holes_inset = 12 mm  # from the edges
param holes_2_d = 3 mm
param holes_2_pitch_x = 46 mm
param holes_2_cols = 2
param holes_2_x = 25.0 mm  # its end member, from the right edge
param holes_2_pitch_y = 23.5 mm
param holes_2_rows = 2
solid plate {
    body = RoundedRectangle(center=(width / 2, height / 2), width=width, height=height, corner_radius=corner_radius)
    Fixed(body)
    # mirrored about the centre line
    for s in [-1, 1] {
        hole holes { h = Circle(center=(10, height / 2 + s * (height / 2 - holes_inset)), diameter=holes_d) }
        Fixed(holes.h)
    }
    # grid: x from its end member, y about its middle
    for i in range(holes_2_cols) {
        for j in range(holes_2_rows) {
            hole holes_2 { h = Circle(center=(width - holes_2_x + (i - (holes_2_cols - 1)) * holes_2_pitch_x, height / 2 + (j - (holes_2_rows - 1) / 2) * holes_2_pitch_y), diameter=holes_2_d) }
            Fixed(holes_2.h)
        }
    }
}
