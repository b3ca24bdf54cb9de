# imported from mega_plate.dxf by `aidl import --infer`: edit freely
# recognised: 14 of 14 pieces of outlines and holes in 11 shapes (10 Circle, 1 Rectangle)
# patterns: 1 corner, 1 equal sizes
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# holes: layer `HOLES` in `OUTLINE`
# 6 holes fit no pattern: one set `holes`, placed from the centre
units mm
param width = 200 mm
param height = 90 mm
param corner_hole_d = 4 mm
param corner_inset = 6 mm  # from the edges
param holes_d = 3.2 mm
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # at the corners, corner_inset in from the edges
    hole corner_holes { h = Circle(center=(corner_inset, corner_inset), diameter=corner_hole_d) }
    CornerPattern(corner_holes, body, inset=corner_inset)
    # 6 holes in no pattern (a board's): one set, from the centre
    for c in [(-52.07, -33.02), (-50.8, 15.24), (0, -27.94), (0, 0), (24.13, 15.24), (30.48, -33.02)] {
        hole holes { h = Circle(center=(width / 2 - 13.96 + c.x, height / 2 + 2.56 + c.y), diameter=holes_d) }
        Fixed(holes.h)
    }
}
