# imported from checker_strip.svg by `aidl import --infer`: edit freely
# recognised: 16 of 16 pieces of outlines and holes in 13 shapes (12 Circle, 1 Rectangle)
# patterns: 1 grid
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 12 holes of 6 mm and 4 mm fill one 6 x 2 lattice together: one pattern, each hole its own size on its turn (not a pattern for each size)
units mm
param width = 150 mm
param height = 50 mm
param holes_d = 6 mm
param holes_pitch = 15 mm
param holes_cols = 8
param holes_x = 12 mm  # its end member, from the left edge
param holes_rows = 2
param holes_small_d = 4 mm  # the holes where (i + j) % 2 == 1
solid plate {
    body = Rectangle(center=(80, -30), width=width, height=height)
    Fixed(body)
    # grid: x from its end member, y about its middle
    for i in range(holes_cols) {
        for j in range(holes_rows) {
            hole holes { h = Circle(center=(80 - width / 2 + holes_x + i * holes_pitch, -30 + (j - (holes_rows - 1) / 2) * holes_pitch), diameter=(holes_small_d if (i + j) % 2 == 1 else holes_d)) }
            Fixed(holes.h)
        }
    }
}
