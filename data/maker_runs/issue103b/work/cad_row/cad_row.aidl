# imported from cad_row.dxf by `aidl import --infer`: edit freely
# recognised: 14 of 14 pieces of outlines and holes in 11 shapes (10 Circle, 1 Rectangle)
# patterns: 1 row, 1 corner
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 6 holes within 0.04 mm of the nodes of one row (CAD rounding): one pattern, 5 of them written off their node as drawn
units mm
param width = 150 mm
param height = 40 mm
param holes_d = 4 mm
param holes_pitch = 22.5 mm
param holes_n = 6
param corner_hole_d = 3 mm
param corner_inset = 6 mm  # from the edges
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # row: x about its middle
    for i in range(holes_n) {
        hole holes { h = Circle(center=(width / 2 + (i - (holes_n - 1) / 2) * holes_pitch + (0.02 if i == 1 else -0.03 if i == 2 else 0.01 if i == 3 else 0.04 if i == 4 else -0.02 if i == 5 else 0), height / 2), diameter=holes_d) }
        Fixed(holes.h)
    }
    # at the corners, corner_inset in from the edges
    hole corner_holes { h = Circle(center=(corner_inset, corner_inset), diameter=corner_hole_d) }
    CornerPattern(corner_holes, body, inset=corner_inset)
}
