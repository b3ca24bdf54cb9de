# imported from pi_plate.dxf by `aidl import --infer`: edit freely
# recognised: 12 of 12 pieces of outlines and holes in 9 shapes (8 Circle, 1 Rectangle)
# patterns: 1 corner, 1 grid
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# holes: layer `HOLES` in `OUTLINE`
units mm
param width = 150 mm
param height = 100 mm
param corner_hole_d = 3.4 mm
param corner_inset = 5 mm  # from the edges
param holes_d = 3.0 mm
param holes_pitch_x = 58 mm
param holes_cols = 2
param holes_pitch_y = 49 mm
param holes_rows = 2
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # at the corners, corner_inset in from the edges
    hole corner_holes { h = Circle(center=(corner_inset, corner_inset), diameter=corner_hole_d) }
    CornerPattern(corner_holes, body, inset=corner_inset)
    # grid: x from its end member, y from its end member
    for i in range(holes_cols) {
        for j in range(holes_rows) {
            hole holes { h = Circle(center=(20 + i * holes_pitch_x, 15 + j * holes_pitch_y), diameter=holes_d) }
            Fixed(holes.h)
        }
    }
}
