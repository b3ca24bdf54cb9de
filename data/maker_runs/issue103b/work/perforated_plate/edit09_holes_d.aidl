# imported from perforated_plate.svg by `aidl import --infer`: edit freely
# recognised: 48 of 48 pieces of outlines and holes in 41 shapes (40 Circle, 1 RoundedRectangle)
# patterns: 1 grid
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
units mm
param width = 120 mm
param height = 80 mm
param corner_radius = 5 mm
param holes_d = 6 mm
param holes_pitch = 10 mm
param holes_cols = 8
param holes_rows = 5
solid plate {
    body = RoundedRectangle(center=(65, -45), width=width, height=height, corner_radius=corner_radius)
    Fixed(body)
    # grid: x about its middle, y about its middle
    for i in range(holes_cols) {
        for j in range(holes_rows) {
            hole holes { h = Circle(center=(65 + (i - (holes_cols - 1) / 2) * holes_pitch, -45 + (j - (holes_rows - 1) / 2) * holes_pitch), diameter=holes_d) }
            Fixed(holes.h)
        }
    }
}
