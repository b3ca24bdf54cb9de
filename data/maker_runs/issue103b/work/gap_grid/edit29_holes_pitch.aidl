# imported from gap_grid.dxf by `aidl import --infer`: edit freely
# recognised: 15 of 15 pieces of outlines and holes in 12 shapes (11 Circle, 1 Rectangle)
# patterns: 1 grid with a gap list
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# holes: layer `HOLES` in `PLATE`
units mm
param width = 150 mm
param height = 90 mm
param holes_d = 6 mm
param holes_pitch = 25 mm
param holes_cols = 4
param holes_rows = 3
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # grid: x about its middle, y about its middle
    for i in range(holes_cols) {
        for j in range(holes_rows) {
            if not (i == 2 and j == 1) {     # the gap: 1 hole of the grid left out, as drawn
                hole holes { h = Circle(center=(width / 2 + (i - (holes_cols - 1) / 2) * holes_pitch, height / 2 + (j - (holes_rows - 1) / 2) * holes_pitch), diameter=holes_d) }
                Fixed(holes.h)
            }
        }
    }
}
