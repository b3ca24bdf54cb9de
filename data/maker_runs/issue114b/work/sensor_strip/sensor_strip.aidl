# imported from sensor_strip.svg by `aidl import --infer`: edit freely
# recognised: 8 of 8 pieces of outlines and holes in 5 shapes (4 Circle, 1 Rectangle)
# patterns: 1 equal sizes
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 3 holes fit no pattern: one set `holes`, placed from the left edge, about the centre line
units mm
param width = 120 mm
param height = 35 mm
param holes_d = 2.5 mm
param holes_x = 10 mm  # the set's hole nearest the corner, from the left edge
param hole1_d = 5 mm
param hole1_x = 10 mm  # its centre, from the right edge
solid plate {
    body = Rectangle(center=(65, -22.5), width=width, height=height)
    Fixed(body)
    # 3 holes in no pattern (a board's): one set, from the left edge, about the centre line
    for c in [(0, 0), (8.25, 18), (16.5, 0)] {
        hole holes { h = Circle(center=(65 - width / 2 + holes_x + c.x, -34 + c.y), diameter=holes_d) }
        Fixed(holes.h)
    }
    hole hole1 { h = Circle(center=(65 + width / 2 - hole1_x, -22.5), diameter=hole1_d) }
    Fixed(hole1.h)
}
