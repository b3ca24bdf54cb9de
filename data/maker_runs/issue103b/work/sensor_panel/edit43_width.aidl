# imported from sensor_panel.dxf by `aidl import --infer`: edit freely
# recognised: 15 of 15 pieces of outlines and holes in 5 shapes (3 Circle, 1 Rectangle, 1 RoundedRectangle)
# patterns: 1 equal sizes
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# holes: layer `HOLES` in `OUTLINE`
# 3 holes fit no pattern: one set `holes`, placed from the top right corner
units mm
param width = 150 mm
param height = 90 mm
param holes_d = 2.7 mm
param holes_x = 23.5 mm  # the set's hole nearest the corner, from the right edge
param holes_y = 10 mm  # the set's hole nearest the corner, from the top edge
param window_width = 40 mm
param window_height = 20 mm
param window_corner_radius = 2 mm
solid plate {
    body = Rectangle(center=(width / 2, height / 2), width=width, height=height)
    Fixed(body)
    # 3 holes in no pattern (a board's): one set, from the top right corner
    for c in [(-11, -17), (0, 0), (11.5, -17)] {
        hole holes { h = Circle(center=(width - holes_x + c.x, height - holes_y + c.y), diameter=holes_d) }
        Fixed(holes.h)
    }
    hole window { h = RoundedRectangle(center=(window_width / 2 + 15, height / 2), width=window_width, height=window_height, corner_radius=window_corner_radius) }
    Fixed(window.h)
}
