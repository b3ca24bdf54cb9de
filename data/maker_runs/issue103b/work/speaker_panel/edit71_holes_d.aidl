# imported from speaker_panel.dxf by `aidl import --infer`: edit freely
# recognised: 62 of 62 pieces of outlines and holes in 55 shapes (54 Circle, 1 RoundedRectangle)
# patterns: 1 corner, 2 grid
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
units mm
param width = 180 mm
param height = 80 mm
param corner_radius = 4 mm
param corner_hole_d = 3.4 mm
param corner_inset = 5 mm  # from the edges
param holes_d = 2.5 mm
param holes_pitch = 6 mm
param holes_cols = 5
param holes_rows = 5
param holes_2_d = 2.5 mm
param holes_2_pitch = 6 mm
param holes_2_cols = 5
param holes_2_rows = 5
solid plate {
    body = RoundedRectangle(center=(width / 2, height / 2), width=width, height=height, corner_radius=corner_radius)
    Fixed(body)
    # at the corners, corner_inset in from the edges
    hole corner_holes { h = Circle(center=(corner_inset, corner_inset), diameter=corner_hole_d) }
    CornerPattern(corner_holes, body, inset=corner_inset)
    # grid: x about its middle, y about its middle
    for i in range(holes_cols) {
        for j in range(holes_rows) {
            hole holes { h = Circle(center=(45 + (i - (holes_cols - 1) / 2) * holes_pitch, height / 2 + (j - (holes_rows - 1) / 2) * holes_pitch), diameter=holes_d) }
            Fixed(holes.h)
        }
    }
    # grid: x about its middle, y about its middle
    for i in range(holes_2_cols) {
        for j in range(holes_2_rows) {
            hole holes_2 { h = Circle(center=(width - 45 + (i - (holes_2_cols - 1) / 2) * holes_2_pitch, height / 2 + (j - (holes_2_rows - 1) / 2) * holes_2_pitch), diameter=holes_2_d) }
            Fixed(holes_2.h)
        }
    }
}
