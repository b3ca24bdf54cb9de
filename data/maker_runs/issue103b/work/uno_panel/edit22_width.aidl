# imported from uno_panel.dxf by `aidl import --infer`: edit freely
# recognised: 13 of 13 pieces of outlines and holes in 10 shapes (9 Circle, 1 Rectangle)
# patterns: 1 corner, 1 equal sizes
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# holes: layer `Drill` in `Edge`
# 4 holes fit no pattern: one set `holes`, placed from the left edge, about the centre line
units mm
param width = 260 mm
param height = 100 mm
param corner_hole_d = 4.2 mm
param corner_inset = 5 mm  # from the edges
param holes_d = 3.2 mm
param holes_x = 23.3 mm  # the set's hole nearest the corner, from the left edge
param hole1_d = 12 mm
solid edge {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # at the corners, corner_inset in from the edges
    hole corner_holes { h = Circle(center=(corner_inset, corner_inset), diameter=corner_hole_d) }
    CornerPattern(corner_holes, body, inset=corner_inset)
    # 4 holes in no pattern (a board's): one set, from the left edge, about the centre line
    for c in [(-1.3, -48.2), (0, 0), (50.8, -43.1), (50.8, -15.2)] {
        hole holes { h = Circle(center=(holes_x + c.x, height / 2 + 20.7 + c.y), diameter=holes_d) }
        Fixed(holes.h)
    }
    hole hole1 { h = Circle(center=(width - 25, height - 30), diameter=hole1_d) }
    Fixed(hole1.h)
}
