# imported from mixed_grid.dxf by `aidl import --infer`: edit freely
# recognised: 24 of 24 pieces of outlines and holes in 21 shapes (20 Circle, 1 Rectangle)
# patterns: 1 grid, 1 corner
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# holes: layer `HOLES` in `PLATE`
# 16 holes of 8 mm and 5 mm fill one 4 x 4 lattice together: one pattern, each hole its own size on its turn (not a pattern for each size)
units mm
param width = 120 mm
param height = 100 mm
param holes_d = 5 mm
param holes_pitch = 20 mm
param holes_cols = 4
param holes_rows = 4
param holes_large_d = 10 mm  # the holes where i == 1 and j == 1 or i == 1 and j == 2 or i == 2 and j == 1 or i == 2 and j == 2
param corner_hole_d = 3.5 mm
param corner_inset = 6 mm  # from the edges
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # grid: x about its middle, y about its middle
    for i in range(holes_cols) {
        for j in range(holes_rows) {
            hole holes { h = Circle(center=(width / 2 + (i - (holes_cols - 1) / 2) * holes_pitch, height / 2 + (j - (holes_rows - 1) / 2) * holes_pitch), diameter=(holes_large_d if i == 1 and j == 1 or i == 1 and j == 2 or i == 2 and j == 1 or i == 2 and j == 2 else holes_d)) }
            Fixed(holes.h)
        }
    }
    # at the corners, corner_inset in from the edges
    hole corner_holes { h = Circle(center=(corner_inset, corner_inset), diameter=corner_hole_d) }
    CornerPattern(corner_holes, body, inset=corner_inset)
}
