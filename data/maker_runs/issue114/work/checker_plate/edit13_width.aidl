# imported from checker_plate.dxf by `aidl import --infer`: edit freely
# recognised: 24 of 24 pieces of outlines and holes in 21 shapes (20 Circle, 1 Rectangle)
# patterns: 1 grid
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# holes: layer `HOLES` in `PLATE`
# 20 holes of 8 mm and 5 mm fill one 5 x 4 lattice together: one pattern, each hole its own size on its turn (not a pattern for each size)
units mm
param width = 220 mm
param height = 110 mm
param holes_d = 8 mm
param holes_pitch = 25 mm
param holes_cols = 5
param holes_rows = 4
param holes_small_d = 5 mm  # the holes where (i + j) % 2 == 1
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # grid: x about its middle, y about its middle
    for i in range(holes_cols) {
        for j in range(holes_rows) {
            hole holes { h = Circle(center=(width / 2 + (i - (holes_cols - 1) / 2) * holes_pitch, height / 2 + (j - (holes_rows - 1) / 2) * holes_pitch), diameter=(holes_small_d if (i + j) % 2 == 1 else holes_d)) }
            Fixed(holes.h)
        }
    }
}
