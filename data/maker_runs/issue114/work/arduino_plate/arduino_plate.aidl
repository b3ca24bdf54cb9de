# imported from arduino_plate.dxf by `aidl import --infer`: edit freely
# recognised: 16 of 16 pieces of outlines and holes in 9 shapes (8 Circle, 1 RoundedRectangle)
# patterns: 1 corner, 1 equal sizes
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 4 holes fit no pattern: one set `holes`, placed from the left edge, about the centre line
units mm
param width = 240 mm
param height = 100 mm
param corner_radius = 4 mm
param corner_hole_d = 4 mm
param corner_inset = 6 mm  # from the edges
param holes_d = 3.2 mm
param holes_x = 30.3 mm  # the set's hole nearest the corner, from the left edge
solid plate {
    body = RoundedRectangle(center=(width / 2, height / 2), width=width, height=height, corner_radius=corner_radius)
    Fixed(body)
    # at the corners, corner_inset in from the edges
    hole corner_holes { h = Circle(center=(corner_inset, corner_inset), diameter=corner_hole_d) }
    CornerPattern(corner_holes, body, inset=corner_inset)
    # 4 holes in no pattern (a board's): one set, from the left edge, about the centre line
    for c in [(-1.3, -48.2), (0, 0), (50.8, -43.1), (50.8, -15.2)] {
        hole holes { h = Circle(center=(holes_x + c.x, height / 2 + 10.7 + c.y), diameter=holes_d) }
        Fixed(holes.h)
    }
}
