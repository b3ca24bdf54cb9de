# imported from mixed_lattice.svg by `aidl import --infer`: edit freely
# recognised: 19 of 19 pieces of outlines and holes in 16 shapes (15 Circle, 1 Rectangle)
# patterns: 1 grid
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 15 holes of 6 mm and 4 mm fill one 5 x 3 lattice together: one pattern, each hole its own size on its turn (not a pattern for each size)
units mm
param width = 150 mm
param height = 70 mm
param holes_d = 6 mm
param holes_pitch_x = 18 mm
param holes_cols = 5
param holes_pitch_y = 15 mm
param holes_rows = 3
param holes_small_d = 4 mm  # the holes where j == 1
solid plate {
    body = Rectangle(center=(70, -40), width=width, height=height)
    Fixed(body)
    # grid: x from its end member, y about its middle
    for i in range(holes_cols) {
        for j in range(holes_rows) {
            hole holes { h = Circle(center=(70 - width / 2 + 12 + i * holes_pitch_x, -40 + (j - (holes_rows - 1) / 2) * holes_pitch_y), diameter=(holes_small_d if j == 1 else holes_d)) }
            Fixed(holes.h)
        }
    }
}
