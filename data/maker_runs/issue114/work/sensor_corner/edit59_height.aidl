# imported from sensor_corner.dxf by `aidl import --infer`: edit freely
# recognised: 11 of 11 pieces of outlines and holes in 8 shapes (7 Circle, 1 Rectangle)
# patterns: 1 corner, 1 equal sizes
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 3 holes fit no pattern: one set `holes`, placed from the top right corner
units mm
param width = 100 mm
param height = 95 mm
param corner_hole_d = 4 mm
param corner_inset = 5 mm  # from the edges
param holes_d = 2.5 mm
param holes_x = 12 mm  # the set's hole nearest the corner, from the right edge
param holes_y = 10 mm  # the set's hole nearest the corner, from the top edge
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # at the corners, corner_inset in from the edges
    hole corner_holes { h = Circle(center=(corner_inset, corner_inset), diameter=corner_hole_d) }
    CornerPattern(corner_holes, body, inset=corner_inset)
    # 3 holes in no pattern (a board's): one set, from the top right corner
    for c in [(-20.3, 0), (-8, -15.2), (0, 0)] {
        hole holes { h = Circle(center=(width - holes_x + c.x, height - holes_y + c.y), diameter=holes_d) }
        Fixed(holes.h)
    }
}
